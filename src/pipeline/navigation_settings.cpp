#include "imu_lab/pipeline/navigation_settings.h"

#include <algorithm>
#include <cmath>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/format_number.h"
#include "imu_lab/common/site_limits.h"
#include "imu_lab/identify/noise_report.h"

namespace imu_lab {
namespace pipeline {

namespace {

// The largest white noise density and bias instability over a triad's axes.
void largest_of_triad(const std::string& path, identify::SensorKind sensor, double& white_density,
                      double& bias_instability) {
  white_density = bias_instability = 0.0;
  for (const identify::ReportedAxisModel& axis : identify::load_reported_axis_models(path, sensor)) {
    double white_squared = axis.model.output_quantization_density * axis.model.output_quantization_density;
    for (const identify::Term& term : axis.model.terms) {
      if (term.kind == identify::TermKind::kWhiteRate) white_squared += term.amplitude * term.amplitude;
      if (term.kind == identify::TermKind::kBiasInstability)
        bias_instability = std::max(bias_instability, term.amplitude);
    }
    white_density = std::max(white_density, std::sqrt(white_squared));
  }
}

}  // namespace

ExpectedSensorErrors expected_errors_from_noise_report(const std::string& path) {
  ExpectedSensorErrors expected;
  largest_of_triad(path, identify::SensorKind::kGyroscope, expected.gyro_noise_density_rad_s_per_sqrt_hz,
                   expected.gyro_bias_rad_s);
  largest_of_triad(path, identify::SensorKind::kAccelerometer, expected.accel_noise_density_m_s2_per_sqrt_hz,
                   expected.accel_bias_m_s2);
  return expected;
}

nav::HeadingSource parse_heading_source(const std::string& key, const std::string& value) {
  if (value == "gyrocompass") return nav::HeadingSource::kGyrocompass;
  if (value == "given") return nav::HeadingSource::kGiven;
  throw ConfigError("navigation settings", key, "is '" + value + "'; use gyrocompass or given");
}

nav::EarthModelConfig parse_earth_model(const std::string& key, const std::string& value) {
  nav::EarthModelConfig config;
  if (value == "wgs84") {
    config.shape = EarthShape::kWgs84Rotating;
  } else if (value == "sphere") {
    config.shape = EarthShape::kSphereNonRotating;
  } else {
    throw ConfigError("navigation settings", key, "is '" + value + "'; use wgs84 or sphere");
  }
  return config;
}

nav::VerticalChannelMode parse_vertical_channel(const std::string& key, const std::string& value) {
  if (value == "free") return nav::VerticalChannelMode::kFree;
  if (value == "held") return nav::VerticalChannelMode::kHeld;
  throw ConfigError("navigation settings", key, "is '" + value + "'; use free or held");
}

void validate(const NavigationSettings& settings, const std::string& source) {
  const auto require = [&](bool ok, const std::string& key, const std::string& problem) {
    if (!ok) throw ConfigError(source, key, problem);
  };
  require(std::abs(settings.latitude_rad) < 0.5 * M_PI, "latitude_deg",
          "must be strictly between -90 and 90 degrees (the ENU mechanisation is singular at the poles)");
  // NaN fails every comparison below, so each check also refuses it.
  const auto within = [](double value, double low, double high) { return value >= low && value <= high; };
  const auto in_degrees = [](double angle_rad) { return angle_rad / kDegToRad; };
  using namespace site_limits;
  require(within(in_degrees(settings.longitude_rad), kLowestLongitudeDeg, kHighestLongitudeDeg), "longitude_deg",
          "must be in [" + format_number(kLowestLongitudeDeg, 6) + ", " + format_number(kHighestLongitudeDeg, 6) +
              "] degrees, got " + format_number(in_degrees(settings.longitude_rad), 6));
  const std::string heights = "[" + format_number(kLowestHeightM, 6) + ", " + format_number(kHighestHeightM, 6) +
                              "] m (the deepest trench to "
                              "the edge of space), got ";
  require(within(settings.height_m, kLowestHeightM, kHighestHeightM), "height_m",
          "must be in " + heights + format_number(settings.height_m, 6));
  const auto& reference_height_m = settings.navigator.vertical.fixed_reference_height_m;
  require(!reference_height_m || within(*reference_height_m, kLowestHeightM, kHighestHeightM), "reference_height_m",
          "must be in " + heights + format_number(reference_height_m.value_or(0.0), 6));
  require(!settings.align || settings.alignment.duration_s > 0.0, "alignment_duration_s",
          "must be a positive number of seconds");
  // One turn either way covers every way of writing an angle; beyond that a number is a mistake
  // (and sin/cos of 1e300 rad is no angle at all). Pitch is within [-90, 90] by definition.
  const auto angle = [&](double angle_rad, double limit_deg, const std::string& key) {
    require(within(in_degrees(angle_rad), -limit_deg, limit_deg), key,
            "must be in [" + format_number(-limit_deg, 6) + ", " + format_number(limit_deg, 6) + "] degrees, got " +
                format_number(in_degrees(angle_rad), 6));
  };
  angle(settings.initial_roll_rad, 360.0, "initial_roll_deg");
  angle(settings.initial_pitch_rad, 90.0, "initial_pitch_deg");
  angle(settings.initial_yaw_rad, 360.0, "initial_yaw_deg");
  angle(settings.alignment.given_yaw_rad, 360.0, "initial_yaw_deg");
  require(!settings.initial_attitude_body_to_enu || (settings.initial_attitude_body_to_enu->coeffs().allFinite() &&
                                                     settings.initial_attitude_body_to_enu->norm() > 0.5),
          "initial attitude", "must be a finite, non-zero quaternion");
  require(settings.initial_velocity_enu_m_s.allFinite(), "initial_velocity_enu_m_s",
          "must be three finite numbers (east, north, up) in m/s");
  require(!settings.align || settings.initial_velocity_enu_m_s.isZero(0.0), "initial_velocity_enu_m_s",
          "is given with a static alignment, which starts at rest; start without alignment (align false, "
          "--no-align) to start moving");
  require(settings.gap_factor > 1.0, "gap_factor", "must be greater than 1 (a gap is that many typical intervals)");
  if (settings.expected_errors) {
    const auto& expected = *settings.expected_errors;
    const auto non_negative = [](double value) { return std::isfinite(value) && value >= 0.0; };
    require(non_negative(expected.gyro_bias_rad_s) && non_negative(expected.accel_bias_m_s2) &&
                non_negative(expected.gyro_noise_density_rad_s_per_sqrt_hz) &&
                non_negative(expected.accel_noise_density_m_s2_per_sqrt_hz),
            "expected sensor errors", "biases and noise densities must be finite, non-negative numbers");
  }
}

Eigen::Vector3d roll_pitch_yaw_from_quaternion(const Eigen::Quaterniond& q_body_to_enu) {
  const Eigen::Matrix3d c = q_body_to_enu.normalized().toRotationMatrix();
  // C = Rz(yaw) Ry(pitch) Rx(roll): C(2,0) = -sin pitch, C(2,1) = cos pitch sin roll, ...
  const double pitch = std::asin(std::max(-1.0, std::min(1.0, -c(2, 0))));
  const double roll = std::atan2(c(2, 1), c(2, 2));
  const double yaw = std::atan2(c(1, 0), c(0, 0));
  return {roll, pitch, yaw};
}

}  // namespace pipeline
}  // namespace imu_lab
