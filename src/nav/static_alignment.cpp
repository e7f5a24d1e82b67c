#include "imu_lab/nav/static_alignment.h"

#include <cmath>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace nav {

namespace {
// A specific force this far from 1 g cannot be a static IMU on the Earth.
constexpr double kMinStaticSpecificForce_m_s2 = 5.0;
constexpr double kMaxStaticSpecificForce_m_s2 = 15.0;
// Below this horizontal rate the east direction is numerical noise: 1 % of the Earth rate, i.e.
// within about 0.6 deg of a pole even with perfect gyros.
constexpr double kMinHorizontalRate_rad_s = 7.3e-7;
}  // namespace

StaticAligner::StaticAligner(const StaticAlignmentConfig& config) : config_(config) {
  if (!(config_.duration_s > 0.0)) {
    throw ConfigError("nav", "alignment.duration_s", "must be a positive number of seconds");
  }
  if (!std::isfinite(config_.given_yaw_rad)) {
    throw ConfigError("nav", "alignment.given_yaw_rad", "must be a finite angle in radians");
  }
}

void StaticAligner::add(const ImuIncrement& increment) {
  validate_increment(increment);
  sum_delta_angle_rad_ += increment.delta_angle_rad;
  sum_delta_velocity_m_s_ += increment.delta_velocity_m_s;
  accumulated_s_ += increment.dt_s;
}

Eigen::Vector3d StaticAligner::mean_angular_rate_rad_s() const {
  return accumulated_s_ > 0.0 ? Eigen::Vector3d(sum_delta_angle_rad_ / accumulated_s_) : Eigen::Vector3d::Zero();
}

Eigen::Vector3d StaticAligner::mean_specific_force_m_s2() const {
  return accumulated_s_ > 0.0 ? Eigen::Vector3d(sum_delta_velocity_m_s_ / accumulated_s_) : Eigen::Vector3d::Zero();
}

Eigen::Quaterniond StaticAligner::attitude() const {
  if (accumulated_s_ <= 0.0) {
    throw InputError("nav alignment: no IMU data yet; feed increments with add() first");
  }
  const Eigen::Vector3d specific_force = mean_specific_force_m_s2();
  const double magnitude = specific_force.norm();
  if (magnitude < kMinStaticSpecificForce_m_s2 || magnitude > kMaxStaticSpecificForce_m_s2) {
    throw InputError("nav alignment: mean specific force is " + std::to_string(magnitude) +
                     " m/s^2, not about 1 g; the IMU is not static or the accelerometer units "
                     "are wrong");
  }
  return config_.heading_source == HeadingSource::kGiven ? levelled_with_given_yaw(specific_force)
                                                         : gyrocompassed(specific_force);
}

Eigen::Quaterniond StaticAligner::levelled_with_given_yaw(const Eigen::Vector3d& f) const {
  // Static: f_body = C_enu^body (0, 0, g); with C_body^enu = Rz(yaw) Ry(pitch) Rx(roll) this is
  // g (-sin pitch, sin roll cos pitch, cos roll cos pitch).
  const double roll = std::atan2(f.y(), f.z());
  const double pitch = std::atan2(-f.x(), std::hypot(f.y(), f.z()));
  return Eigen::Quaterniond(Eigen::AngleAxisd(config_.given_yaw_rad, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .normalized();
}

Eigen::Quaterniond StaticAligner::gyrocompassed(const Eigen::Vector3d& f) const {
  const Eigen::Vector3d up = f.normalized();
  const Eigen::Vector3d east_unnormalised = mean_angular_rate_rad_s().cross(up);
  if (east_unnormalised.norm() < kMinHorizontalRate_rad_s) {
    throw InputError("nav alignment: horizontal Earth rate is " + std::to_string(east_unnormalised.norm()) +
                     " rad/s, too small to gyrocompass (near a pole, or gyros too noisy); set "
                     "alignment heading_source to given and supply given_yaw_rad");
  }
  const Eigen::Vector3d east = east_unnormalised.normalized();
  const Eigen::Vector3d north = up.cross(east);
  Eigen::Matrix3d body_to_enu;  // rows: ENU axes expressed in body coordinates
  body_to_enu.row(0) = east.transpose();
  body_to_enu.row(1) = north.transpose();
  body_to_enu.row(2) = up.transpose();
  return Eigen::Quaterniond(body_to_enu).normalized();
}

void StaticAligner::reset() {
  sum_delta_angle_rad_.setZero();
  sum_delta_velocity_m_s_.setZero();
  accumulated_s_ = 0.0;
}

}  // namespace nav
}  // namespace imu_lab
