// One IMU output interval as the strapdown mechanisation consumes it: the integrated angular
// rate (delta angle) and integrated specific force (delta velocity) in the IMU body frame
// (REP-145: x forward, y left, z up), over dt_s seconds.
//
// The coning and sculling corrections (coning_sculling.h) are derived for true increments, i.e.
// integrals over the interval. A rate sample that is the sensor's average over its interval turns
// into the exact increment by multiplying with dt (increment_from_mean_rates). A point sample of the
// rate multiplied by dt is only an approximation of the increment; the corrections then fix
// errors the data do not contain and can add their own.
#pragma once

#include <Eigen/Core>

namespace imu_lab {
namespace nav {

struct ImuIncrement {
  Eigen::Vector3d delta_angle_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d delta_velocity_m_s = Eigen::Vector3d::Zero();
  double dt_s = 0.0;
};

// Increment from interval-average angular rate (rad/s) and specific force (m/s^2):
// increment = average * dt. Throws InputError for a non-positive or non-finite dt or non-finite
// rates.
ImuIncrement increment_from_mean_rates(const Eigen::Vector3d& mean_angular_rate_rad_s,
                                       const Eigen::Vector3d& mean_specific_force_m_s2, double dt_s);

// Throws InputError naming what is wrong if the increment cannot be integrated.
void validate_increment(const ImuIncrement& increment);

}  // namespace nav
}  // namespace imu_lab
