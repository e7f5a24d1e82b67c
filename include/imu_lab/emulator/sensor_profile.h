// Sensor error-model profile: per triad, output = b + K * input + nonlinearity + g-sensitivity
// + noise (seed 001 section 3.3), with K = I + diag(scale_factor_error) + misalignment.
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

// Temperature dependence of one triad (seed 001 eq. 4.1, per axis), with dT = T - T_ref:
//   bias         += sum_k bias_polynomial[k] dT^(k+1) + bias_per_temperature_rate * dT/dt   [u]
//   scale factor += sum_k scale_factor_polynomial_ppm[k] dT^(k+1)
//                   + scale_factor_ppm_per_temperature_rate * dT/dt                         [ppm]
// Empty polynomials and zero rate terms (the default) leave the triad temperature-independent.
struct ThermalSensitivity {
  double reference_temperature_c = 20.0;
  std::vector<Eigen::Vector3d> bias_polynomial;              // row k: [u / degC^(k+1)]
  std::vector<Eigen::Vector3d> scale_factor_polynomial_ppm;  // row k: [ppm / degC^(k+1)]
  Eigen::Vector3d bias_per_temperature_rate = Eigen::Vector3d::Zero();              // [u / (degC/s)]
  Eigen::Vector3d scale_factor_ppm_per_temperature_rate = Eigen::Vector3d::Zero();  // [ppm / (degC/s)]

  Eigen::Vector3d bias(double temperature_c, double temperature_rate_c_s) const;
  Eigen::Vector3d scale_factor_ppm(double temperature_c, double temperature_rate_c_s) const;
};

// One triad (gyro or accelerometer). "u" = rad/s (gyro) or m/s^2 (accelerometer); "v" = rad or m/s.
struct TriadErrorModel {
  Eigen::Vector3d bias_fixed = Eigen::Vector3d::Zero();           // [u]
  Eigen::Vector3d bias_turn_on_sigma = Eigen::Vector3d::Zero();   // run-to-run 1-sigma [u]
  Eigen::Vector3d scale_factor_error_ppm = Eigen::Vector3d::Zero();
  // Off-diagonal small-angle misalignment / non-orthogonality [rad]; the diagonal is zero.
  Eigen::Matrix3d misalignment_rad = Eigen::Matrix3d::Zero();
  // output_i += c_i * input_i^2  [1/u]
  Eigen::Vector3d quadratic_nonlinearity_per_unit = Eigen::Vector3d::Zero();
  // Gyro only: rate error = G * specific_force  [rad/s per m/s^2]. Zero for accelerometers.
  Eigen::Matrix3d g_sensitivity = Eigen::Matrix3d::Zero();
  // Anti-alias low-pass corner (first order); 0 = none. Applied exactly to the white rate noise
  // (white -> Gauss-Markov); see sensor_channel.h for what it does not filter.
  double bandwidth_hz = 0.0;
  // Physical quantization: cumulative increment rounded to whole pulses of this weight [v]
  // with carry; 0 = none. (The white-angle model is a noise process instead.)
  double pulse_weight = 0.0;
  // Independent noise processes per axis (x, y, z), each switchable and combinable.
  std::array<std::vector<noise::ProcessParameters>, 3> noise_per_axis;
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
