#include "imu_lab/nav/imu_increment.h"

#include <cmath>
#include <string>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace nav {

void validate_increment(const ImuIncrement& increment) {
  if (!std::isfinite(increment.dt_s) || increment.dt_s <= 0.0) {
    throw InputError("nav: IMU increment has dt_s = " + std::to_string(increment.dt_s) +
                     "; it must be a positive number of seconds (check the sample stamps)");
  }
  if (!increment.delta_angle_rad.allFinite() || !increment.delta_velocity_m_s.allFinite()) {
    throw InputError("nav: IMU increment contains NaN or Inf; drop the sample or fix the driver");
  }
}

ImuIncrement increment_from_mean_rates(const Eigen::Vector3d& mean_angular_rate_rad_s,
                                       const Eigen::Vector3d& mean_specific_force_m_s2, double dt_s) {
  ImuIncrement increment;
  increment.delta_angle_rad = mean_angular_rate_rad_s * dt_s;
  increment.delta_velocity_m_s = mean_specific_force_m_s2 * dt_s;
  increment.dt_s = dt_s;
  validate_increment(increment);
  return increment;
}

}  // namespace nav
}  // namespace imu_lab
