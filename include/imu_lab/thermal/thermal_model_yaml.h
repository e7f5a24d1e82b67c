// Thermal model files (YAML). Saving is atomic; loading is strict: every refusal is a
// ConfigError naming the dotted key. Schema (u = rad_s for the gyro, m_s2 for the accelerometer):
//   format: imu_lab_thermal_model      version: 1
//   reference_temperature_c, rate_window_s, uses_temperature_rate, uses_second_sensor
//   validity: {temperature_min_c, temperature_max_c, rate_min_c_s, rate_max_c_s,
//              second_temperature_min_c, second_temperature_max_c (with the second sensor)}
//   gyro / accelerometer: {x, y, z: {bias_polynomial_<u>: [per degC, per degC^2, ...],
//              bias_per_temperature_rate_<u>_per_c_s, bias_second_sensor_polynomial_<u>,
//              scale_factor_polynomial_ppm, scale_factor_ppm_per_temperature_rate_per_c_s,
//              scale_factor_second_sensor_polynomial_ppm (optional)}}
//   regime_switch: {threshold_c_s2, window_s, hold_s} (optional; with it dynamic_gyro and
//              dynamic_accelerometer, the same keys as gyro / accelerometer, for the dynamic regime)
//   fit: (optional, written by fit_thermal and not read back) orders, residuals, uncertainties.
#pragma once

#include <string>

#include "imu_lab/thermal/thermal_fit.h"
#include "imu_lab/thermal/thermal_model.h"

namespace imu_lab {
namespace thermal {

ThermalModel load_thermal_model(const std::string& path);
std::string thermal_model_to_yaml(const ThermalModel& model, const ThermalFitResult* fit);
// Atomic; `fit` (may be null) adds the fit section.
void save_thermal_model(const std::string& path, const ThermalModel& model, const ThermalFitResult* fit);

}  // namespace thermal
}  // namespace imu_lab
