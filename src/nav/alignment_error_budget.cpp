#include "imu_lab/nav/alignment_error_budget.h"

#include <cmath>

namespace imu_lab {
namespace nav {

Eigen::Vector3d predicted_alignment_error_rad(const Eigen::Vector3d& gyro_bias_body_rad_s,
                                              const Eigen::Vector3d& accel_bias_body_m_s2,
                                              const Eigen::Quaterniond& q_body_to_enu, double latitude_rad,
                                              double gravity_m_s2, double earth_rate_rad_s) {
  const Eigen::Vector3d accel_bias_enu = q_body_to_enu * accel_bias_body_m_s2;
  const Eigen::Vector3d gyro_bias_enu = q_body_to_enu * gyro_bias_body_rad_s;
  const double horizontal_earth_rate = earth_rate_rad_s * std::cos(latitude_rad);
  return Eigen::Vector3d(
      accel_bias_enu.y() / gravity_m_s2, -accel_bias_enu.x() / gravity_m_s2,
      gyro_bias_enu.x() / horizontal_earth_rate - accel_bias_enu.x() * std::tan(latitude_rad) / gravity_m_s2);
}

Eigen::Matrix3d alignment_noise_covariance_rad2(double gyro_angle_random_walk_rad_per_sqrt_s,
                                                double accel_velocity_random_walk_m_s_per_sqrt_s, double duration_s,
                                                double latitude_rad, double gravity_m_s2, double earth_rate_rad_s) {
  // Averages of white noise over T: variance N^2 / T per axis, isotropic, so the body attitude
  // does not matter.
  const double accel_mean_variance =
      accel_velocity_random_walk_m_s_per_sqrt_s * accel_velocity_random_walk_m_s_per_sqrt_s / duration_s;
  const double gyro_mean_variance =
      gyro_angle_random_walk_rad_per_sqrt_s * gyro_angle_random_walk_rad_per_sqrt_s / duration_s;
  const double tilt_variance = accel_mean_variance / (gravity_m_s2 * gravity_m_s2);
  const double horizontal_earth_rate = earth_rate_rad_s * std::cos(latitude_rad);
  const double tan_latitude = std::tan(latitude_rad);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  covariance(0, 0) = tilt_variance;
  covariance(1, 1) = tilt_variance;
  covariance(2, 2) = gyro_mean_variance / (horizontal_earth_rate * horizontal_earth_rate) +
                     tan_latitude * tan_latitude * tilt_variance;
  covariance(1, 2) = covariance(2, 1) = tan_latitude * tilt_variance;
  return covariance;
}

}  // namespace nav
}  // namespace imu_lab
