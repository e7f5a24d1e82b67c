#include "imu_lab/calib/calibration_file.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/yaml_fields.h"

namespace imu_lab {
namespace calib {
namespace {

constexpr const char* kFormat = "imu_lab_calibration_1";
constexpr double kDegPerHour = kDegPerRad * 3600.0;

std::string vector_text(const Eigen::Vector3d& v) {
  std::ostringstream text;
  text << std::setprecision(12) << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
  return text.str();
}

void write_matrix(std::ostream& out, const std::string& key, const Eigen::Matrix3d& m) {
  out << "  " << key << ":\n";
  for (int row = 0; row < 3; ++row) out << "    - " << vector_text(m.row(row).transpose()) << "\n";
}

Eigen::Matrix3d block(const ParameterVector& values, int offset) {
  Eigen::Matrix3d m;
  for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = values[offset + k];
  return m;
}

TriadCalibration read_triad(const YamlFields& file, const std::string& triad_key, const std::string& bias_key) {
  const YamlFields triad = file.child(triad_key);
  TriadCalibration calibration;
  calibration.bias = triad.per_axis(bias_key, false);
  calibration.scale_misalignment = triad.matrix3("scale_misalignment");
  if (std::abs(calibration.scale_misalignment.determinant()) < 1e-6) {
    triad.fail("scale_misalignment", "is singular: it cannot be inverted for the correction");
  }
  calibration.g_sensitivity = triad.matrix3_or_zero("g_sensitivity_rad_s_per_m_s2");
  return calibration;
}

}  // namespace

std::string calibration_yaml(const CalibrationResult& result) {
  using namespace parameter_offset;
  std::ostringstream out;
  out << std::setprecision(12);
  out << "# imu_lab calibration (fit_calibration). Correct with input = K^-1 (output - bias - G f),\n"
      << "# accelerometers first (the gyro's G needs the corrected specific force). Sigmas are 1-sigma.\n";
  out << "format: " << kFormat << "\n";
  out << "model: \"output = bias + K * input (+ G * specific_force, gyro); input = K^-1 (output - bias - G f)\"\n";
  out << "mode: " << (result.known_orientations ? "known_orientations" : "unknown_orientations") << "\n";
  out << "frame: \"" << result.frame_convention << "\"\n";
  const auto triad = [&](const std::string& name, const TriadCalibration& t, int bias_offset, int k_offset,
                         const std::string& unit) {
    out << name << ":\n";
    out << "  bias_" << unit << ": " << vector_text(t.bias) << "\n";
    out << "  bias_sigma_" << unit << ": " << vector_text(result.sigmas.segment<3>(bias_offset)) << "\n";
    write_matrix(out, "scale_misalignment", t.scale_misalignment);
    write_matrix(out, "scale_misalignment_sigma", block(result.sigmas, k_offset));
    out << "  scale_factor_error_ppm: " << vector_text(t.scale_factor_error_ppm()) << "\n";
    write_matrix(out, "misalignment_arcsec", t.misalignment_arcsec());
  };
  triad("gyro", result.calibration.gyro, kGyroBias, kGyroK, "rad_s");
  write_matrix(out, "g_sensitivity_rad_s_per_m_s2", result.calibration.gyro.g_sensitivity);
  write_matrix(out, "g_sensitivity_sigma_rad_s_per_m_s2", block(result.sigmas, kGyroGSensitivity));
  out << "  g_sensitivity_estimated: " << (result.estimated[kGyroGSensitivity] ? "true" : "false") << "\n";
  triad("accelerometer", result.calibration.accelerometer, kAccelerometerBias, kAccelerometerK, "m_s2");
  out << "noise:  # white-noise densities from block means inside the rests (continuous time)\n";
  out << "  gyro_white_density_rad_s_per_sqrt_hz: " << vector_text(result.noise.rate_density_rad_s_per_sqrt_hz) << "\n";
  out << "  accelerometer_white_density_m_s2_per_sqrt_hz: " << vector_text(result.noise.force_density_m_s2_per_sqrt_hz)
      << "\n";
  std::size_t held_out = 0;
  for (const auto& rest : result.rests) held_out += rest.held_out ? 1 : 0;
  out << "fit:\n";
  out << "  rests: " << result.rests.size() << "\n  held_out_rests: " << held_out << "\n";
  out << "  moves: " << result.moves.size() << "\n";
  out << "  residuals: " << result.residual_count << "\n  free_parameters: " << result.free_parameter_count << "\n";
  out << "  chi2_per_dof: " << result.chi2_per_degree_of_freedom << "\n";
  out << "  condition_number: " << result.condition_number << "\n";
  out << "  static_window_s: " << result.detection.window_s << "\n";
  out << "  static_threshold_rad_s: " << result.detection.threshold_rad_s << "\n";
  const auto& g = result.held_out.gravity_m_s2;
  const auto& w = result.held_out.earth_rate_rad_s;
  out << "held_out_check:  # spread (std) over the held-out rests of |g| and |Earth rate|\n";
  out << "  rests: " << g.rests << "\n";
  out << "  gravity_spread_raw_m_s2: " << g.raw_spread << "\n";
  out << "  gravity_spread_corrected_m_s2: " << g.corrected_spread << "\n";
  out << "  gravity_spread_expected_m_s2: " << g.expected_spread << "\n";
  out << "  earth_rate_spread_raw_deg_h: " << w.raw_spread * kDegPerHour << "\n";
  out << "  earth_rate_spread_corrected_deg_h: " << w.corrected_spread * kDegPerHour << "\n";
  out << "  earth_rate_spread_expected_deg_h: " << w.expected_spread * kDegPerHour << "\n";
  return out.str();
}

ImuCalibration load_calibration(const std::string& path) {
  const YAML::Node root = load_yaml_file(path);
  // A scalar or a list at the top (a truncated or wrong file) has no keys to look up.
  if (!root.IsMap())
    throw ConfigError(path, "(file)", "must be a YAML map of keys (write the file with fit_calibration)");
  const YamlFields file(root, "", path);
  if (!file.has("format") || file.text("format") != kFormat) {
    file.fail("format", std::string("must be ") + kFormat + " (write the file with fit_calibration)");
  }
  ImuCalibration calibration;
  calibration.gyro = read_triad(file, "gyro", "bias_rad_s");
  calibration.accelerometer = read_triad(file, "accelerometer", "bias_m_s2");
  calibration.accelerometer.g_sensitivity.setZero();
  return calibration;
}

}  // namespace calib
}  // namespace imu_lab
