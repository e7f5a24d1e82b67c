// Evaluation of a triad's temperature terms (sensor_profile.h, ThermalSensitivity).
#include "imu_lab/emulator/sensor_profile.h"

namespace imu_lab {
namespace emulator {

namespace {
// sum_k rows[k] dT^(k+1) by Horner's rule.
Eigen::Vector3d polynomial_without_constant(const std::vector<Eigen::Vector3d>& rows, double dt) {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  for (auto row = rows.rbegin(); row != rows.rend(); ++row) value = (value + *row) * dt;
  return value;
}
}  // namespace

Eigen::Vector3d ThermalSensitivity::bias(double temperature_c, double temperature_rate_c_s,
                                         std::optional<double> second_temperature_c) const {
  return polynomial_without_constant(bias_polynomial, temperature_c - reference_temperature_c) +
         bias_per_temperature_rate * temperature_rate_c_s +
         polynomial_without_constant(bias_second_sensor_polynomial,
                                     second_temperature_c.value_or(temperature_c) - reference_temperature_c);
}

Eigen::Vector3d ThermalSensitivity::scale_factor_ppm(double temperature_c, double temperature_rate_c_s,
                                                     std::optional<double> second_temperature_c) const {
  return polynomial_without_constant(scale_factor_polynomial_ppm, temperature_c - reference_temperature_c) +
         scale_factor_ppm_per_temperature_rate * temperature_rate_c_s +
         polynomial_without_constant(scale_factor_second_sensor_polynomial_ppm,
                                     second_temperature_c.value_or(temperature_c) - reference_temperature_c);
}

}  // namespace emulator
}  // namespace imu_lab
