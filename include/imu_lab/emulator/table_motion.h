// A body on a turntable at a fixed site: a sequence of rotation phases, each about a fixed ENU
// axis with a constant angular acceleration (so a dwell, a constant rate, a rate change and the
// three parts of a trapezoidal move are all one kind of phase). Attitude in a phase:
//   C(tau) = Rot(axis_enu, angle(tau)) * C_start,  angle = rate0 tau + accel tau^2 / 2,
// and the rate w.r.t. ENU in body axes is angle'(tau) * C_start^T axis_enu (constant direction).
// Multi-position sequences and rate tables both build their phases with RotationPhaseBuilder.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "imu_lab/emulator/kinematic_motion.h"
#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

struct RotationPhase {
  double start_s = 0.0;
  double duration_s = 0.0;  // the last phase is open-ended (infinity)
  Eigen::Vector3d axis_enu = Eigen::Vector3d::UnitZ();
  Eigen::Quaterniond start_attitude_body_to_enu = Eigen::Quaterniond::Identity();
  double start_rate_rad_s = 0.0;
  double acceleration_rad_s2 = 0.0;

  double angle_rad(double elapsed_s) const;
  double rate_rad_s(double elapsed_s) const;
  Eigen::Quaterniond attitude_body_to_enu(double elapsed_s) const;
};

// Appends phases, each starting where the previous one ended (time, attitude, rate).
class RotationPhaseBuilder {
 public:
  explicit RotationPhaseBuilder(const Eigen::Quaterniond& initial_attitude_body_to_enu);
  // At rest in `attitude` (snapped exactly, so a dwell sees its configured orientation).
  void dwell(const Eigen::Quaterniond& attitude_body_to_enu, double duration_s);
  // Rest-to-rest turn by angle_rad (> 0) about axis_enu: accelerate, cruise at max_rate,
  // decelerate; triangular when the angle is too short to reach max_rate.
  void trapezoidal_turn(const Eigen::Vector3d& axis_enu, double angle_rad, double max_rate_rad_s,
                        double acceleration_rad_s2);
  // From the current rate to target_rate at |acceleration| (axis fixed for a rate table).
  void change_rate(const Eigen::Vector3d& axis_enu, double target_rate_rad_s, double acceleration_rad_s2);
  void hold_rate(const Eigen::Vector3d& axis_enu, double duration_s);
  // The phases plus an open-ended one continuing the final rate.
  std::vector<RotationPhase> finish() const;

 private:
  void append(const Eigen::Vector3d& axis_enu, double duration_s, double acceleration_rad_s2);

  std::vector<RotationPhase> phases_;
  double time_s_ = 0.0;
  double rate_rad_s_ = 0.0;
  Eigen::Vector3d axis_enu_ = Eigen::Vector3d::UnitZ();
  Eigen::Quaterniond attitude_;
};

class TableMotion : public KinematicMotion {
 public:
  // Site (position, Earth model, temperature) from the scenario's common keys.
  TableMotion(const ScenarioConfig& site, std::vector<RotationPhase> phases);
  TruthState truth_at(double time_s) const override;

 protected:
  const std::vector<double>& breakpoints_s() const override { return breakpoints_s_; }
  double longest_smooth_piece_s() const override { return longest_piece_s_; }

 private:
  ScenarioConfig site_;
  std::vector<RotationPhase> phases_;
  std::vector<double> breakpoints_s_;
  double longest_piece_s_ = 1.0;
};

}  // namespace emulator
}  // namespace imu_lab
