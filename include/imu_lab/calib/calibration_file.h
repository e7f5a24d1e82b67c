// The calibration YAML (written atomically by fit_calibration, read by calibration_corrector):
//   format: imu_lab_calibration_1
//   model: "output = bias + K * input (+ G * specific_force, gyro); input = K^-1 (output - bias - G f)"
//   mode: known_orientations | unknown_orientations
//   frame: the frame the corrected data are in (see bench_calibration.h)
//   gyro:          {bias_rad_s, bias_sigma_rad_s, scale_misalignment (K, rows), scale_misalignment_sigma,
//                   g_sensitivity_rad_s_per_m_s2, g_sensitivity_sigma_rad_s_per_m_s2,
//                   scale_factor_error_ppm, misalignment_arcsec}
//   accelerometer: {bias_m_s2, bias_sigma_m_s2, scale_misalignment, scale_misalignment_sigma,
//                   scale_factor_error_ppm, misalignment_arcsec}
//   noise:         {gyro_white_density_rad_s_per_sqrt_hz, accelerometer_white_density_m_s2_per_sqrt_hz}
//   fit:           {rests, held_out, moves, chi2_per_dof, condition_number, static_threshold_rad_s, ...}
//   held_out_check: {gravity_spread_*_m_s2, earth_rate_spread_*_deg_h}
// Only bias, scale_misalignment and (optionally) g_sensitivity are read back; the rest informs.
#pragma once

#include <string>

#include "imu_lab/calib/bench_calibration.h"
#include "imu_lab/calib/imu_calibration.h"

namespace imu_lab {
namespace calib {

std::string calibration_yaml(const CalibrationResult& result);
// Throws ConfigError naming the key that is missing or wrong (e.g. a singular K).
ImuCalibration load_calibration(const std::string& path);

}  // namespace calib
}  // namespace imu_lab
