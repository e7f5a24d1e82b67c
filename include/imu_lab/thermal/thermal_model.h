// Temperature model of an IMU and its correction (Golovach 2017 sections 3.2 and 4.2, eq. 3.17 and
// 4.1). Per axis, with dT = T - T_ref (T the main thermosensor, T2 the optional second, lagging
// one, dT2 = T2 - T_ref, and Tdot the rate of change of T):
//   delta_bias  = sum_k b_k dT^(k+1) + b_rate Tdot + sum_k e_k dT2^(k+1)                [u]
//   delta_scale = 1e-6 (sum_k s_k dT^(k+1) + s_rate Tdot + sum_k f_k dT2^(k+1))          [-]
//   corrected   = (raw - delta_bias) / (1 + delta_scale)
// With the regime switch (Golovach 2017 eqs. 3.18, 3.19) a second set of terms applies while the
// temperature's second derivative says the regime is dynamic (thermal_regime.h).
// i.e. the output the sensor would give at the reference temperature: thermal compensation
// comes first in the chain, calibration (bias, scale factor, misalignment) is fitted and
// applied on compensated data. Outside the validity box seen in the thermal test, the inputs are
// clamped to its edge and the correction is flagged.
// "u" = rad/s (gyro) or m/s^2 (accelerometer).
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace imu_lab {
namespace thermal {

struct AxisThermalTerms {
  std::vector<double> bias_polynomial;                            // row k: [u / degC^(k+1)]
  double bias_per_temperature_rate = 0.0;                         // [u / (degC/s)]
  std::vector<double> bias_second_sensor_polynomial;              // row k: [u / degC^(k+1)] in dT2
  std::vector<double> scale_factor_polynomial_ppm;                // row k: [ppm / degC^(k+1)]
  double scale_factor_ppm_per_temperature_rate = 0.0;             // [ppm / (degC/s)]
  std::vector<double> scale_factor_second_sensor_polynomial_ppm;  // row k: [ppm / degC^(k+1)] in dT2
};

using TriadThermalTerms = std::array<AxisThermalTerms, 3>;

// The box of inputs the thermal test covered.
struct ThermalValidity {
  double temperature_min_c = 0.0;
  double temperature_max_c = 0.0;
  double rate_min_c_s = 0.0;
  double rate_max_c_s = 0.0;
  double second_temperature_min_c = 0.0;  // used only with the second-sensor term
  double second_temperature_max_c = 0.0;
};

// The regime switch of Golovach 2017 eqs. 3.18, 3.19: dynamic while |d2T/dt2| of the main
// thermosensor, estimated causally over window_s, exceeded threshold_c_s2 within the last hold_s.
struct RegimeSwitchSettings {
  bool enabled = false;
  double threshold_c_s2 = 0.0;  // [degC/s^2]
  double window_s = 300.0;      // of the second-derivative estimate (TemperatureHistory)
  double hold_s = 0.0;          // the thesis's delay: the dynamic regime outlasts the indicator
};

struct ThermalModel {
  double reference_temperature_c = 20.0;
  // The rate of change is estimated the same way in the fit and when applying (see
  // TemperatureHistory::rate_at): over this window ending at the sample's stamp.
  double rate_window_s = 60.0;
  bool uses_temperature_rate = false;
  bool uses_second_sensor = false;
  ThermalValidity validity;
  TriadThermalTerms gyro;
  TriadThermalTerms accelerometer;
  // Used instead of gyro / accelerometer in the dynamic regime (only with regime_switch.enabled).
  RegimeSwitchSettings regime_switch;
  TriadThermalTerms dynamic_gyro;
  TriadThermalTerms dynamic_accelerometer;
};

// The thermosensor readings matched to one IMU sample by its stamp.
struct ThermalInput {
  double temperature_c = 0.0;
  double rate_c_s = 0.0;
  std::optional<double> second_temperature_c;
  bool dynamic_regime = false;  // used only by a model with the regime switch
};

struct ThermalCorrection {
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();
  bool clamped = false;  // an input was outside the validity box and was held at its edge
};

// The validity range of the inputs the model uses (only those clamp), for messages:
// "-20.1 .. 60.2 degC, -0.0042 .. 0.0189 degC/s".
std::string validity_range_text(const ThermalModel& model);

// The input clamped into the validity box (and whether it had to be).
ThermalInput clamp_to_validity(const ThermalModel& model, const ThermalInput& input, bool* clamped);

// Per-axis deviations at an input already inside the validity box.
double axis_delta_bias(const ThermalModel& model, const AxisThermalTerms& terms, const ThermalInput& input);
double axis_delta_scale(const ThermalModel& model, const AxisThermalTerms& terms, const ThermalInput& input);

// Throws std::invalid_argument if the model uses the second sensor and the input has none.
ThermalCorrection correct(const ThermalModel& model, const Eigen::Vector3d& angular_rate_rad_s,
                          const Eigen::Vector3d& specific_force_m_s2, const ThermalInput& input);

// sum_k coefficients[k] x^(k+1)
double polynomial_without_constant(const std::vector<double>& coefficients, double x);

}  // namespace thermal
}  // namespace imu_lab
