// Sensor error-model profile: per triad, output = b + K * input + nonlinearity + g-sensitivity
// + noise (Golovach 2017 section 3.3), with K = I + diag(scale_factor_error) + misalignment, then the
// output register's LSB.
// Loaded from YAML with strict validation (every refusal is a ConfigError naming the dotted key).
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "imu_lab/noise/process_parameters.h"

namespace YAML {
class Node;
}

namespace imu_lab {
namespace emulator {

// Temperature dependence of one triad (Golovach 2017 eq. 4.1, per axis), with dT = T - T_ref:
//   bias         += sum_k bias_polynomial[k] dT^(k+1) + bias_per_temperature_rate * dT/dt   [u]
//   scale factor += sum_k scale_factor_polynomial_ppm[k] dT^(k+1)
//                   + scale_factor_ppm_per_temperature_rate * dT/dt                         [ppm]
// and, in the second thermosensor's dT2 = T2 - T_ref (a part of the IMU lagging the first, the ADC
// board of eq. 4.1; without a second sensor in the scenario, T2 = T):
//   bias         += sum_k bias_second_sensor_polynomial[k] dT2^(k+1)                       [u]
//   scale factor += sum_k scale_factor_second_sensor_polynomial_ppm[k] dT2^(k+1)            [ppm]
// Empty polynomials and zero rate terms (the default) leave the triad temperature-independent.
struct ThermalSensitivity {
  double reference_temperature_c = 20.0;
  std::vector<Eigen::Vector3d> bias_polynomial;                                     // row k: [u / degC^(k+1)]
  std::vector<Eigen::Vector3d> scale_factor_polynomial_ppm;                         // row k: [ppm / degC^(k+1)]
  Eigen::Vector3d bias_per_temperature_rate = Eigen::Vector3d::Zero();              // [u / (degC/s)]
  Eigen::Vector3d scale_factor_ppm_per_temperature_rate = Eigen::Vector3d::Zero();  // [ppm / (degC/s)]
  std::vector<Eigen::Vector3d> bias_second_sensor_polynomial;                       // row k: [u / degC^(k+1)] in dT2
  std::vector<Eigen::Vector3d> scale_factor_second_sensor_polynomial_ppm;           // row k: [ppm / degC^(k+1)] in dT2

  bool uses_second_sensor() const {
    return !bias_second_sensor_polynomial.empty() || !scale_factor_second_sensor_polynomial_ppm.empty();
  }
  // second_temperature_c: empty = the same as temperature_c (no second sensor in the scenario).
  Eigen::Vector3d bias(double temperature_c, double temperature_rate_c_s,
                       std::optional<double> second_temperature_c = std::nullopt) const;
  Eigen::Vector3d scale_factor_ppm(double temperature_c, double temperature_rate_c_s,
                                   std::optional<double> second_temperature_c = std::nullopt) const;
};

// One triad (gyro or accelerometer). "u" = rad/s (gyro) or m/s^2 (accelerometer); "v" = rad or m/s.
struct TriadErrorModel {
  Eigen::Vector3d bias_fixed = Eigen::Vector3d::Zero();          // [u]
  Eigen::Vector3d bias_turn_on_sigma = Eigen::Vector3d::Zero();  // run-to-run 1-sigma [u]
  Eigen::Vector3d scale_factor_error_ppm = Eigen::Vector3d::Zero();
  // Off-diagonal small-angle misalignment / non-orthogonality [rad]; the diagonal is zero.
  Eigen::Matrix3d misalignment_rad = Eigen::Matrix3d::Zero();
  // Rate-dependent scale-factor errors of axis i, in its input w_i (IEEE Std 528 terms):
  //   + c2_i w_i^2 + c3_i w_i^3 + 1e-6 A_i / 2 |w_i|   (K+ - K- = A_i ppm of K)
  // The profile gives c2, c3 either directly or in ppm of full scale FS at full scale:
  // c2 = 1e-6 k2 / FS, c3 = 1e-6 k3 / FS^2.
  Eigen::Vector3d quadratic_nonlinearity_per_unit = Eigen::Vector3d::Zero();  // c2 [1/u]
  Eigen::Vector3d cubic_nonlinearity_per_unit2 = Eigen::Vector3d::Zero();     // c3 [1/u^2]
  Eigen::Vector3d scale_factor_asymmetry_ppm = Eigen::Vector3d::Zero();       // A
  // The axis's whole rate-dependent response (K, thermal scale and the terms above) reads zero
  // while its magnitude is below this [u]; 0 = none.
  Eigen::Vector3d dead_zone = Eigen::Vector3d::Zero();
  // Gyro only: rate error = G * specific_force  [rad/s per m/s^2]. Zero for accelerometers.
  Eigen::Matrix3d g_sensitivity = Eigen::Matrix3d::Zero();
  // Anti-alias low-pass corner (first order); 0 = none. Applied exactly to the white rate noise
  // (white -> Gauss-Markov); see sensor_channel.h for what it does not filter.
  double bandwidth_hz = 0.0;
  // Physical quantization: cumulative increment rounded to whole pulses of this weight [v]
  // with carry; 0 = none. (The white-angle model is a noise process instead.)
  double pulse_weight = 0.0;
  // The output register: every output sample (rate, hence increment) rounded to a whole number
  // of this step [u], last, after the anti-alias filter, the pulses and every error; 0 = none.
  Eigen::Vector3d output_lsb = Eigen::Vector3d::Zero();
  // Noise processes per axis (x, y, z), each switchable and combinable; independent across axes
  // except the white rate noise, whose three axes are correlated by white_rate_correlation.
  std::array<std::vector<noise::ProcessParameters>, 3> noise_per_axis;
  // Correlation matrix of the three axes' white rate noise (applied through its Cholesky factor
  // to the unit-variance white deviates, before the anti-alias filter, which is the same on all
  // axes and so keeps it). Identity = independent.
  Eigen::Matrix3d white_rate_correlation = Eigen::Matrix3d::Identity();
  ThermalSensitivity thermal;

  // K = I + diag(scale_factor_error_ppm * 1e-6) + misalignment_rad.
  Eigen::Matrix3d scale_misalignment_matrix() const;
};

struct SensorProfile {
  std::string name;
  std::string source;  // file it came from (for messages)
  TriadErrorModel gyro;
  TriadErrorModel accelerometer;
};

// Throws ConfigError (key = dotted path, e.g. "gyro.noise.markov[1].correlation_time_s").
SensorProfile load_sensor_profile(const std::string& path);
SensorProfile sensor_profile_from_yaml(const YAML::Node& root, const std::string& source_name);

}  // namespace emulator
}  // namespace imu_lab
