#include "imu_lab/calib/calibration_report.h"

#include <cstdio>
#include <string>

namespace imu_lab {
namespace calib {
namespace {

constexpr double kDegPerHour = kDegPerRad * 3600.0;
constexpr double kMicroGPerM_s2 = 1e6 / 9.80665;

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0, double e = 0.0,
                   double f = 0.0) {
  char line[512];
  std::snprintf(line, sizeof line, pattern, a, b, c, d, e, f);
  return line;
}

// One triad's parameters: bias, scale-factor errors and misalignments with their sigmas.
std::string triad_section(const CalibrationResult& result, bool gyro) {
  using namespace parameter_offset;
  const TriadCalibration& t = gyro ? result.calibration.gyro : result.calibration.accelerometer;
  const int bias = gyro ? kGyroBias : kAccelerometerBias;
  const int k = gyro ? kGyroK : kAccelerometerK;
  const double bias_scale = gyro ? kDegPerHour : kMicroGPerM_s2;
  std::string text = gyro ? "gyro (bias in deg/h)\n" : "accelerometer (bias in micro-g)\n";
  const char* axes = "xyz";
  for (int i = 0; i < 3; ++i) {
    text += std::string("  ") + axes[i] +
            format(": bias %+12.4f +- %9.4f   scale factor error %+10.2f +- %6.2f ppm\n", t.bias[i] * bias_scale,
                   result.sigmas[bias + i] * bias_scale, (t.scale_misalignment(i, i) - 1.0) * 1e6,
                   result.sigmas[k + 4 * i] * 1e6);
  }
  text += "  misalignment K_ij [arcsec] (row = sensor, column = input axis; 'fixed' = frame convention)\n";
  for (int i = 0; i < 3; ++i) {
    text += "   ";
    for (int j = 0; j < 3; ++j) {
      if (i == j) {
        text += "            -          ";
      } else if (!result.estimated[k + 3 * i + j]) {
        text += "          fixed        ";
      } else {
        text += format(" %+10.2f +- %7.2f ", t.scale_misalignment(i, j) * kArcsecPerRad,
                       result.sigmas[k + 3 * i + j] * kArcsecPerRad);
      }
    }
    text += "\n";
  }
  return text;
}

}  // namespace

std::string calibration_report(const CalibrationResult& result) {
  std::string text = "imu_lab bench calibration\n";
  text += std::string("mode: ") +
          (result.known_orientations ? "known orientations (table schedule)" : "unknown orientations") + "\n";
  text += "frame: " + result.frame_convention + "\n";
  text += format("rests: %.0f (window %.3f s, threshold %.3e rad/s); moves used: %.0f\n",
                 static_cast<double>(result.rests.size()), result.detection.window_s, result.detection.threshold_rad_s,
                 static_cast<double>(result.moves.size()));
  text += format("residuals %.0f, free parameters %.0f, chi2/dof %.3f, condition number %.3g\n",
                 static_cast<double>(result.residual_count), static_cast<double>(result.free_parameter_count),
                 result.chi2_per_degree_of_freedom, result.condition_number);
  text += "solver: " + result.solver_report + "\n";
  for (const std::string& warning : result.warnings) text += "WARNING: " + warning + "\n";
  text += "\n";
  text += triad_section(result, true);
  if (result.estimated[parameter_offset::kGyroGSensitivity]) {
    text += "  g-sensitivity G [deg/h per g], rows x y z:\n";
    const Eigen::Matrix3d g = result.calibration.gyro.g_sensitivity * kDegPerHour * 9.80665;
    for (int i = 0; i < 3; ++i) text += format("    %+10.4f %+10.4f %+10.4f\n", g(i, 0), g(i, 1), g(i, 2));
  }
  text += "\n" + triad_section(result, false);
  text +=
      format("\nnoise (white density from the rests): gyro %.3e rad/s/sqrt(Hz), accelerometer %.3e m/s^2/sqrt(Hz)\n",
             result.noise.rate_density_rad_s_per_sqrt_hz.mean(), result.noise.force_density_m_s2_per_sqrt_hz.mean());

  text += "\nrests: measured - model (fitted rests); held-out rests are only checked\n";
  text += "   #    start_s  duration_s  held_out  force_residual_m_s2 (x y z)           rate_residual_deg_h (x y z)\n";
  for (std::size_t r = 0; r < result.rests.size(); ++r) {
    const RestReport& rest = result.rests[r];
    const Eigen::Vector3d& f = rest.force_residual_m_s2;
    const Eigen::Vector3d w = rest.rate_residual_rad_s * kDegPerHour;
    text += format("%4.0f %10.3f %11.3f", static_cast<double>(r + 1), rest.means.start_s, rest.means.duration_s);
    text += rest.held_out ? "       yes\n"
                          : format("        no  %+11.3e %+11.3e %+11.3e  %+10.4f %+10.4f %+10.4f\n", f.x(), f.y(),
                                   f.z(), w.x(), w.y(), w.z());
  }
  text += "\nmoves: integrated corrected rotation vs. the known (mode 1) or estimated (mode 2) one\n";
  text += "  from  to  duration_s  angle_deg  residual_arcsec (x y z)\n";
  for (const MoveReport& move : result.moves) {
    const Eigen::Vector3d a = move.angle_residual_rad * kArcsecPerRad;
    text += format("  %4.0f %3.0f %11.3f %10.3f  %+9.3f %+9.3f", static_cast<double>(move.from + 1),
                   static_cast<double>(move.to + 1), move.duration_s, move.angle_rad * kDegPerRad, a.x(), a.y());
    text += format(" %+9.3f\n", a.z());
  }
  const InvariantSpread& g = result.held_out.gravity_m_s2;
  const InvariantSpread& w = result.held_out.earth_rate_rad_s;
  text += format(
      "\nheld-out check over %.0f rests not used for fitting (Golovach 2017 sec. 5.4-5.5; thesis: 3e-4 m/s^2, "
      "0.001 deg/h measured, 0.015 deg/h allowed)\n",
      static_cast<double>(g.rests));
  if (g.rests < 2) {
    text += "  (fewer than 2 held-out rests: hold some out with --held-out-last N to check)\n";
  } else {
    text += format(
        "  |g|:          spread raw %.3e, corrected %.3e, expected %.3e m/s^2; mean error %+.3e m/s^2 "
        "(reference %.6f)\n",
        g.raw_spread, g.corrected_spread, g.expected_spread, g.corrected_mean_error, g.reference);
    text += format("  |Earth rate|: spread raw %.5f, corrected %.5f, expected %.5f deg/h; mean error %+.5f deg/h\n",
                   w.raw_spread * kDegPerHour, w.corrected_spread * kDegPerHour, w.expected_spread * kDegPerHour,
                   w.corrected_mean_error * kDegPerHour);
  }
  return text;
}

}  // namespace calib
}  // namespace imu_lab
