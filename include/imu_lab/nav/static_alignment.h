// Initial attitude on a static base from averaged IMU increments.
//  - Levelling: the mean specific force is "up" (Fomichev 2022 §1.1: tg D(0) = g_p2 / g_p1, in 3-D).
//  - Heading, kGyrocompass: the mean angular rate is Earth rate; up x Earth rate points east
//    (ENU: (W cos L N + W sin L U) x U = W cos L E), so no latitude is needed. Needs gyros whose
//    noise averaged over duration_s is well below W cos L (about 1e-5 rad/s at 50 deg).
//  - Heading, kGiven: for gyros too noisy to gyrocompass; yaw about ENU z, from east towards north
//    (REP-103), combined with the levelled roll and pitch.
// Starting from a fully given attitude (no self-levelling) needs no aligner: pass the attitude to
// Navigator::initialise.
// Expected errors from sensor biases and noise: alignment_error_budget.h.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "imu_lab/nav/imu_increment.h"

namespace imu_lab {
namespace nav {

enum class HeadingSource { kGyrocompass, kGiven };

struct StaticAlignmentConfig {
  double duration_s = 300.0;
  HeadingSource heading_source = HeadingSource::kGyrocompass;
  double given_yaw_rad = 0.0;  // used with kGiven
};

class StaticAligner {
 public:
  explicit StaticAligner(const StaticAlignmentConfig& config = StaticAlignmentConfig());

  // Increments recorded while the IMU stands still.
  void add(const ImuIncrement& increment);
  bool complete() const { return accumulated_s_ >= config_.duration_s; }
  double accumulated_s() const { return accumulated_s_; }
  Eigen::Vector3d mean_angular_rate_rad_s() const;
  Eigen::Vector3d mean_specific_force_m_s2() const;

  // Body->ENU attitude from the data so far (normally called once complete()). Throws InputError
  // if there is no data, the specific force is not gravity-like, or (gyrocompassing) the
  // horizontal Earth rate cannot be resolved (near a pole, or far too noisy gyros).
  Eigen::Quaterniond attitude() const;

  void reset();

 private:
  Eigen::Quaterniond levelled_with_given_yaw(const Eigen::Vector3d& specific_force) const;
  Eigen::Quaterniond gyrocompassed(const Eigen::Vector3d& specific_force) const;

  StaticAlignmentConfig config_;
  Eigen::Vector3d sum_delta_angle_rad_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_delta_velocity_m_s_ = Eigen::Vector3d::Zero();
  double accumulated_s_ = 0.0;
};

}  // namespace nav
}  // namespace imu_lab
