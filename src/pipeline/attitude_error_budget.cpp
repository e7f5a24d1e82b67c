#include "imu_lab/pipeline/attitude_error_budget.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/format_number.h"
#include "imu_lab/emulator/motion_source.h"
#include "imu_lab/identify/noise_report.h"
#include "imu_lab/nav/earth_model.h"

namespace imu_lab {
namespace pipeline {

namespace {
nav::EarthModel scenario_earth(const emulator::ScenarioConfig& scenario) {
  nav::EarthModelConfig config;
  config.shape = scenario.earth_model;
  return nav::EarthModel(config);
}

long long step_count(double duration_s, double step_s) {
  if (!(duration_s > 0.0)) {
    throw ConfigError("attitude motion", "--duration-s", "no duration: the scenario has none, give one");
  }
  if (!(step_s > 0.0) || step_s > duration_s) {
    throw ConfigError("attitude motion", "--step-s", "must be > 0 and at most the duration");
  }
  return std::llround(duration_s / step_s);
}
}  // namespace

std::vector<nav::AttitudeSample> scenario_attitude_motion(const emulator::ScenarioConfig& scenario, double duration_s,
                                                          double step_s) {
  const double duration = duration_s > 0.0 ? duration_s : scenario.duration_s;
  const long long steps = step_count(duration, step_s);
  const nav::EarthModel earth = scenario_earth(scenario);
  const std::unique_ptr<emulator::MotionSource> source = emulator::make_motion_source(scenario);
  std::vector<nav::AttitudeSample> motion;
  motion.reserve(static_cast<std::size_t>(steps) + 1);
  for (long long k = 0; k <= steps; ++k) {
    const emulator::TruthState truth = source->truth_at(k * step_s);
    nav::AttitudeSample sample;
    sample.time_s = k * step_s;
    sample.body_to_navigation = truth.attitude_body_to_enu;
    sample.navigation_rate_rad_s =
        earth.earth_rate_enu_rad_s(truth.latitude_rad) +
        earth.transport_rate_enu_rad_s(truth.velocity_enu_m_s, truth.latitude_rad, truth.height_m);
    motion.push_back(sample);
  }
  return motion;
}

std::vector<nav::AttitudeSample> constant_rate_scenario_motion(const emulator::ScenarioConfig& site,
                                                               const Eigen::Vector3d& body_rate_rad_s,
                                                               double duration_s, double step_s) {
  step_count(duration_s, step_s);
  const Eigen::Quaterniond start = Eigen::AngleAxisd(site.yaw_rad, Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(site.pitch_rad, Eigen::Vector3d::UnitY()) *
                                   Eigen::AngleAxisd(site.roll_rad, Eigen::Vector3d::UnitX());
  return nav::constant_rate_motion(body_rate_rad_s, start, scenario_earth(site).earth_rate_enu_rad_s(site.latitude_rad),
                                   duration_s, step_s);
}

std::array<nav::GyroAxisErrors, 3> gyros_from_noise_report(const std::string& path, double turn_on_bias_rad_s) {
  const auto axes = identify::load_reported_axis_models(path, identify::SensorKind::kGyroscope);
  std::array<nav::GyroAxisErrors, 3> gyros;
  for (int i = 0; i < 3; ++i) {
    gyros[i].model = axes[i].model;
    gyros[i].sample_interval_s = axes[i].tau0_s;
    gyros[i].constant_bias_sigma_rad_s = turn_on_bias_rad_s;
  }
  return gyros;
}

std::string attitude_error_csv(const std::vector<nav::AttitudeErrorPoint>& points) {
  std::string csv =
      "time_s,strapdown_east_rad,strapdown_north_rad,strapdown_up_rad,platform_east_rad,platform_north_rad,"
      "platform_up_rad,strapdown_total_rad,platform_total_rad\n";
  for (const nav::AttitudeErrorPoint& point : points) {
    csv += format_number(point.time_s);
    for (const Eigen::Vector3d& sigma : {point.strapdown_sigma_rad(), point.platform_sigma_rad()}) {
      for (int axis = 0; axis < 3; ++axis) csv += "," + format_number(sigma[axis]);
    }
    csv += "," + format_number(std::sqrt(point.strapdown_covariance_rad2.trace()));
    csv += "," + format_number(std::sqrt(point.platform_covariance_rad2.trace())) + "\n";
  }
  return csv;
}

std::string attitude_error_summary(const std::vector<nav::AttitudeErrorPoint>& points) {
  constexpr double kRadToDeg = 180.0 / M_PI;
  std::ostringstream out;
  out << "  time_s   strapdown E, N, U [deg]          platform E, N, U [deg]           total ratio\n";
  std::vector<std::size_t> rows;
  for (double decade = 1.0; !points.empty() && decade < points.back().time_s; decade *= 10.0) {
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (points[k].time_s >= decade) {
        if (rows.empty() || rows.back() != k) rows.push_back(k);
        break;
      }
    }
  }
  if (!points.empty()) rows.push_back(points.size() - 1);
  for (std::size_t k : rows) {
    const nav::AttitudeErrorPoint& point = points[k];
    out << format_printf(point.time_s, "%8.1f");
    for (const Eigen::Vector3d& sigma : {point.strapdown_sigma_rad(), point.platform_sigma_rad()}) {
      out << "  ";
      for (int axis = 0; axis < 3; ++axis) out << format_printf(sigma[axis] * kRadToDeg, " %9.3e");
    }
    const double platform = point.platform_covariance_rad2.trace();
    out << "  "
        << (platform > 0.0 ? format_printf(std::sqrt(point.strapdown_covariance_rad2.trace() / platform), "%6.3f")
                           : std::string("     -"))
        << "\n";
  }
  return out.str();
}

double largest_step_turn_rad(const std::vector<nav::AttitudeSample>& motion) {
  double largest = 0.0;
  for (std::size_t k = 1; k < motion.size(); ++k) {
    largest = std::max(largest, motion[k - 1].body_to_navigation.angularDistance(motion[k].body_to_navigation));
  }
  return largest;
}

}  // namespace pipeline
}  // namespace imu_lab
