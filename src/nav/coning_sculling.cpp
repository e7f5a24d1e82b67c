#include "imu_lab/nav/coning_sculling.h"

#include <Eigen/Geometry>

namespace imu_lab {
namespace nav {

ConingScullingCompensator::ConingScullingCompensator(const ConingScullingConfig& config) : config_(config) {}

CompensatedIncrement ConingScullingCompensator::compensate(const ImuIncrement& increment) {
  const Eigen::Vector3d& angle = increment.delta_angle_rad;
  const Eigen::Vector3d& velocity = increment.delta_velocity_m_s;
  CompensatedIncrement out;
  out.rotation_vector_rad = angle;
  if (config_.coning_correction) {
    out.rotation_vector_rad += previous_delta_angle_rad_.cross(angle) / 12.0;
  }
  out.delta_velocity_m_s = velocity + 0.5 * angle.cross(velocity);
  if (config_.sculling_correction) {
    out.delta_velocity_m_s +=
        (previous_delta_angle_rad_.cross(velocity) + previous_delta_velocity_m_s_.cross(angle)) / 12.0;
  }
  previous_delta_angle_rad_ = angle;
  previous_delta_velocity_m_s_ = velocity;
  return out;
}

void ConingScullingCompensator::reset() {
  previous_delta_angle_rad_.setZero();
  previous_delta_velocity_m_s_.setZero();
}

}  // namespace nav
}  // namespace imu_lab
