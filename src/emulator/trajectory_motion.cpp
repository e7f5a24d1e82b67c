#include "imu_lab/emulator/trajectory_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "imu_lab/emulator/local_level_kinematics.h"
#include "imu_lab/emulator/scenario_motions.h"

namespace imu_lab {
namespace emulator {

namespace {
constexpr double kNodeSpacing_s = 0.25;
}

TrajectoryMotion::TrajectoryMotion(const ScenarioConfig& scenario) : scenario_(scenario) {
  const TrajectoryConfig& config = scenario.trajectory.value();
  Leg leg;
  leg.start_speed_m_s = config.initial_speed_m_s;
  leg.start_yaw_rad = config.initial_yaw_rad;
  double fastest_turn_rad_s = 0.0;
  for (const TrajectoryConfig::Leg& configured : config.legs) {
    leg.duration_s = configured.duration_s;
    leg.acceleration_m_s2 = configured.acceleration_m_s2;
    leg.yaw_rate_rad_s = configured.yaw_rate_rad_s;
    legs_.push_back(leg);
    fastest_turn_rad_s = std::max(fastest_turn_rad_s, std::abs(leg.yaw_rate_rad_s));
    leg.start_s += leg.duration_s;
    leg.start_speed_m_s += leg.acceleration_m_s2 * leg.duration_s;
    leg.start_yaw_rad += leg.yaw_rate_rad_s * leg.duration_s;
  }
  leg.duration_s = std::numeric_limits<double>::infinity();
  leg.acceleration_m_s2 = 0.0;  // afterwards: same speed and turn rate
  legs_.push_back(leg);
  for (const Leg& l : legs_) leg_starts_s_.push_back(l.start_s);
  longest_piece_s_ = std::min(1.0, 1.0 / std::max(fastest_turn_rad_s, 1e-9));
  nodes_.push_back({0.0, 0, scenario.latitude_rad, scenario.longitude_rad});
}

std::size_t TrajectoryMotion::leg_index(double time_s) const {
  auto after = std::upper_bound(leg_starts_s_.begin(), leg_starts_s_.end(), time_s);
  return after == leg_starts_s_.begin() ? 0 : static_cast<std::size_t>(after - leg_starts_s_.begin()) - 1;
}

Eigen::Vector3d TrajectoryMotion::velocity_enu_m_s(const Leg& leg, double time_s) const {
  const double elapsed = time_s - leg.start_s;
  const double speed = leg.start_speed_m_s + leg.acceleration_m_s2 * elapsed;
  const double yaw = leg.start_yaw_rad + leg.yaw_rate_rad_s * elapsed;
  return {speed * std::cos(yaw), speed * std::sin(yaw), 0.0};
}

TrajectoryMotion::PositionNode TrajectoryMotion::position_step(const PositionNode& from, double to_s) const {
  const Leg& leg = legs_[from.leg];
  const double h = scenario_.height_m;
  auto rates = [&](double t, double latitude) -> Eigen::Vector2d {
    const Eigen::Vector3d v = velocity_enu_m_s(leg, t);
    const RadiiOfCurvature radii = radii_of_curvature(scenario_.earth_model, latitude);
    return {v.y() / (radii.meridian_m + h), v.x() / ((radii.prime_vertical_m + h) * std::cos(latitude))};
  };
  const double dt = to_s - from.time_s;
  const double t0 = from.time_s;
  const Eigen::Vector2d k1 = rates(t0, from.latitude_rad);
  const Eigen::Vector2d k2 = rates(t0 + 0.5 * dt, from.latitude_rad + 0.5 * dt * k1.x());
  const Eigen::Vector2d k3 = rates(t0 + 0.5 * dt, from.latitude_rad + 0.5 * dt * k2.x());
  const Eigen::Vector2d k4 = rates(t0 + dt, from.latitude_rad + dt * k3.x());
  const Eigen::Vector2d change = dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  return {to_s, from.leg, from.latitude_rad + change.x(), from.longitude_rad + change.y()};
}

const TrajectoryMotion::PositionNode& TrajectoryMotion::node_before(double time_s) const {
  while (nodes_.back().time_s + kNodeSpacing_s <= time_s ||
         (nodes_.back().leg + 1 < legs_.size() && legs_[nodes_.back().leg + 1].start_s <= time_s)) {
    const PositionNode& last = nodes_.back();
    const double leg_end = legs_[last.leg].start_s + legs_[last.leg].duration_s;
    PositionNode next = position_step(last, std::min(last.time_s + kNodeSpacing_s, leg_end));
    if (next.time_s >= leg_end) next.leg = last.leg + 1;
    nodes_.push_back(next);
  }
  auto after = std::upper_bound(nodes_.begin(), nodes_.end(), time_s,
                                [](double t, const PositionNode& node) { return t < node.time_s; });
  return after == nodes_.begin() ? nodes_.front() : *(after - 1);
}

TruthState TrajectoryMotion::truth_at(double time_s) const {
  const double t = std::max(0.0, time_s);
  const PositionNode position = position_step(node_before(t), t);
  const Leg& leg = legs_[leg_index(t)];
  const double elapsed = t - leg.start_s;
  const double speed = leg.start_speed_m_s + leg.acceleration_m_s2 * elapsed;
  const double yaw = leg.start_yaw_rad + leg.yaw_rate_rad_s * elapsed;
  const Eigen::Vector3d along(std::cos(yaw), std::sin(yaw), 0.0);
  const Eigen::Vector3d left(-std::sin(yaw), std::cos(yaw), 0.0);

  LocalLevelMotion motion;
  motion.latitude_rad = position.latitude_rad;
  motion.longitude_rad = position.longitude_rad;
  motion.height_m = scenario_.height_m;
  motion.velocity_enu_m_s = speed * along;
  motion.acceleration_enu_m_s2 = leg.acceleration_m_s2 * along + speed * leg.yaw_rate_rad_s * left;
  motion.attitude_body_to_enu = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  motion.rate_body_wrt_enu_rad_s = Eigen::Vector3d(0.0, 0.0, leg.yaw_rate_rad_s);
  return truth_from_local_level(motion, scenario_.earth_model, time_s, scenario_.temperature_c);
}

std::unique_ptr<MotionSource> make_trajectory_motion(const ScenarioConfig& scenario) {
  return std::make_unique<TrajectoryMotion>(scenario);
}

}  // namespace emulator
}  // namespace imu_lab
