#include "imu_lab/pipeline/attitude_error_budget.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
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

Eigen::Quaterniond site_start_attitude(const emulator::ScenarioConfig& site) {
  return Eigen::AngleAxisd(site.yaw_rad, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(site.pitch_rad, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(site.roll_rad, Eigen::Vector3d::UnitX());
}

std::vector<nav::AttitudeSample> constant_rate_scenario_motion(const emulator::ScenarioConfig& site,
                                                               const Eigen::Vector3d& body_rate_rad_s,
                                                               double duration_s, double step_s) {
  step_count(duration_s, step_s);
  return nav::constant_rate_motion(body_rate_rad_s, site_start_attitude(site),
                                   scenario_earth(site).earth_rate_enu_rad_s(site.latitude_rad), duration_s, step_s);
}

namespace {
void check_recorded_stamps(const std::vector<io::ImuRecord>& records) {
  if (records.size() < 2) throw std::invalid_argument("the motion needs at least two IMU samples");
  std::vector<std::int64_t> intervals_ns;
  for (std::size_t i = 1; i < records.size(); ++i) {
    if (records[i].stamp_ns <= records[i - 1].stamp_ns) {
      throw std::invalid_argument("the IMU stamps do not increase at " + format_stamp_s(records[i].stamp_ns) + " s");
    }
    intervals_ns.push_back(records[i].stamp_ns - records[i - 1].stamp_ns);
  }
  std::nth_element(intervals_ns.begin(), intervals_ns.begin() + intervals_ns.size() / 2, intervals_ns.end());
  const std::int64_t median_ns = intervals_ns[intervals_ns.size() / 2];
  for (std::size_t i = 1; i < records.size(); ++i) {
    if (records[i].stamp_ns - records[i - 1].stamp_ns > 10 * median_ns) {
      throw std::invalid_argument("a gap in the IMU stamps before " + format_stamp_s(records[i].stamp_ns) +
                                  " s (more than 10 median intervals): the motion there is unknown");
    }
  }
}
}  // namespace

std::vector<nav::AttitudeSample> recorded_attitude_motion(const std::vector<io::ImuRecord>& records,
                                                          const emulator::ScenarioConfig& site, double duration_s,
                                                          double step_s) {
  check_recorded_stamps(records);
  const double span_s = seconds_between(records.front().stamp_ns, records.back().stamp_ns);
  const double duration = duration_s > 0.0 ? duration_s : step_s * std::floor(span_s / step_s * (1.0 + 1e-12));
  if (duration > span_s * (1.0 + 1e-9)) {
    throw std::invalid_argument("the duration asked, " + std::to_string(duration) + " s, exceeds the recording's " +
                                std::to_string(span_s) + " s");
  }
  const long long steps = step_count(duration, step_s);
  const Eigen::Vector3d earth_rate_enu = scenario_earth(site).earth_rate_enu_rad_s(site.latitude_rad);
  std::vector<nav::AttitudeSample> motion;
  motion.reserve(static_cast<std::size_t>(steps) + 1);
  nav::AttitudeSample current;
  current.body_to_navigation = site_start_attitude(site);
  current.navigation_rate_rad_s = earth_rate_enu;
  motion.push_back(current);
  // Turns the body over dt at record i's rate relative to ENU: the Earth rate is projected with
  // the attitude at mid-interval (a first pass with the attitude at its start finds it), so the
  // error per step is of order W w^2 dt^3 rather than W w dt^2.
  const auto rotation = [](const Eigen::Vector3d& rate_rad_s, double dt_s) {
    const double angle = rate_rad_s.norm() * dt_s;
    return angle > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, rate_rad_s.normalized()))
                       : Eigen::Quaterniond::Identity();
  };
  const auto turn = [&](std::size_t i, double dt_s) {
    const Eigen::Quaterniond& q = current.body_to_navigation;
    const Eigen::Vector3d first = records[i].angular_rate_rad_s - q.conjugate() * earth_rate_enu;
    const Eigen::Quaterniond middle = q * rotation(first, 0.5 * dt_s);
    const Eigen::Vector3d body_rate = records[i].angular_rate_rad_s - middle.conjugate() * earth_rate_enu;
    current.body_to_navigation = (q * rotation(body_rate, dt_s)).normalized();
  };
  double time_s = 0.0;
  for (std::size_t i = 1; i < records.size() && static_cast<long long>(motion.size()) <= steps; ++i) {
    const double interval_end_s = seconds_between(records.front().stamp_ns, records[i].stamp_ns);
    // Every grid point inside this interval: turn up to it and record the attitude there.
    while (static_cast<long long>(motion.size()) <= steps) {
      const double grid_s = static_cast<double>(motion.size()) * step_s;
      if (grid_s > interval_end_s) break;
      turn(i, grid_s - time_s);
      time_s = grid_s;
      current.time_s = grid_s;
      motion.push_back(current);
    }
    turn(i, interval_end_s - time_s);
    time_s = interval_end_s;
  }
  if (static_cast<long long>(motion.size()) <= steps) {  // the last grid point at the last stamp
    current.time_s = static_cast<double>(motion.size()) * step_s;
    motion.push_back(current);
  }
  return motion;
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
