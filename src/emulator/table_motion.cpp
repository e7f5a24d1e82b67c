#include "imu_lab/emulator/table_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "imu_lab/emulator/local_level_kinematics.h"

namespace imu_lab {
namespace emulator {

double RotationPhase::angle_rad(double elapsed_s) const {
  return elapsed_s * (start_rate_rad_s + 0.5 * acceleration_rad_s2 * elapsed_s);
}

double RotationPhase::rate_rad_s(double elapsed_s) const { return start_rate_rad_s + acceleration_rad_s2 * elapsed_s; }

Eigen::Quaterniond RotationPhase::attitude_body_to_enu(double elapsed_s) const {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad(elapsed_s), axis_enu)) * start_attitude_body_to_enu;
}

RotationPhaseBuilder::RotationPhaseBuilder(const Eigen::Quaterniond& initial_attitude_body_to_enu)
    : attitude_(initial_attitude_body_to_enu) {}

void RotationPhaseBuilder::append(const Eigen::Vector3d& axis_enu, double duration_s, double acceleration_rad_s2) {
  if (!(duration_s > 0.0)) return;
  RotationPhase phase;
  phase.start_s = time_s_;
  phase.duration_s = duration_s;
  phase.axis_enu = axis_enu.normalized();
  phase.start_attitude_body_to_enu = attitude_;
  phase.start_rate_rad_s = rate_rad_s_;
  phase.acceleration_rad_s2 = acceleration_rad_s2;
  phases_.push_back(phase);
  time_s_ += duration_s;
  rate_rad_s_ = phase.rate_rad_s(duration_s);
  attitude_ = phase.attitude_body_to_enu(duration_s).normalized();
  axis_enu_ = phase.axis_enu;
}

void RotationPhaseBuilder::dwell(const Eigen::Quaterniond& attitude_body_to_enu, double duration_s) {
  if (rate_rad_s_ != 0.0) throw std::logic_error("RotationPhaseBuilder::dwell while turning");
  attitude_ = attitude_body_to_enu.normalized();
  append(axis_enu_, duration_s, 0.0);
}

void RotationPhaseBuilder::trapezoidal_turn(const Eigen::Vector3d& axis_enu, double angle_rad, double max_rate_rad_s,
                                            double acceleration_rad_s2) {
  // Reaching max_rate and stopping again takes max_rate^2 / acceleration of angle.
  const double peak_rate = std::min(max_rate_rad_s, std::sqrt(angle_rad * acceleration_rad_s2));
  const double ramp_s = peak_rate / acceleration_rad_s2;
  const double cruise_s = (angle_rad - peak_rate * ramp_s) / peak_rate;
  append(axis_enu, ramp_s, acceleration_rad_s2);
  rate_rad_s_ = peak_rate;  // exact, not ramp_s * acceleration rounded
  append(axis_enu, cruise_s, 0.0);
  append(axis_enu, ramp_s, -acceleration_rad_s2);
  rate_rad_s_ = 0.0;
}

void RotationPhaseBuilder::change_rate(const Eigen::Vector3d& axis_enu, double target_rate_rad_s,
                                       double acceleration_rad_s2) {
  const double change = target_rate_rad_s - rate_rad_s_;
  append(axis_enu, std::abs(change) / acceleration_rad_s2, std::copysign(acceleration_rad_s2, change));
  rate_rad_s_ = target_rate_rad_s;
}

void RotationPhaseBuilder::hold_rate(const Eigen::Vector3d& axis_enu, double duration_s) {
  append(axis_enu, duration_s, 0.0);
}

std::vector<RotationPhase> RotationPhaseBuilder::finish() const {
  std::vector<RotationPhase> phases = phases_;
  RotationPhase last;
  last.start_s = time_s_;
  last.duration_s = std::numeric_limits<double>::infinity();
  last.axis_enu = axis_enu_;
  last.start_attitude_body_to_enu = attitude_;
  last.start_rate_rad_s = rate_rad_s_;
  phases.push_back(last);
  return phases;
}

TableMotion::TableMotion(const ScenarioConfig& site, std::vector<RotationPhase> phases)
    : site_(site), phases_(std::move(phases)) {
  if (phases_.empty()) throw std::invalid_argument("TableMotion: no phases");
  double fastest_rad_s = 0.0;
  for (const RotationPhase& phase : phases_) {
    breakpoints_s_.push_back(phase.start_s);
    fastest_rad_s = std::max(
        {fastest_rad_s, std::abs(phase.start_rate_rad_s), std::abs(phase.rate_rad_s(std::min(phase.duration_s, 1e9)))});
  }
  // The Earth rate turns in body axes at the table rate: keep that under 1 rad per piece.
  longest_piece_s_ = std::min(1.0, 1.0 / std::max(fastest_rad_s, 1e-9));
}

TruthState TableMotion::truth_at(double time_s) const {
  auto after = std::upper_bound(breakpoints_s_.begin(), breakpoints_s_.end(), time_s);
  const std::size_t index = after == breakpoints_s_.begin() ? 0 : (after - breakpoints_s_.begin()) - 1;
  const RotationPhase& phase = phases_[index];
  // Before the first phase the table waits at its starting attitude.
  const double elapsed_s = std::max(0.0, time_s - phase.start_s);
  LocalLevelMotion motion;
  motion.latitude_rad = site_.latitude_rad;
  motion.longitude_rad = site_.longitude_rad;
  motion.height_m = site_.height_m;
  motion.attitude_body_to_enu = phase.attitude_body_to_enu(elapsed_s);
  motion.rate_body_wrt_enu_rad_s =
      phase.rate_rad_s(elapsed_s) * (phase.start_attitude_body_to_enu.conjugate() * phase.axis_enu);
  return truth_from_local_level(motion, site_.earth_model, time_s, site_.temperature_c);
}

}  // namespace emulator
}  // namespace imu_lab
