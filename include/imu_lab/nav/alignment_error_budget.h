// Expected static-alignment errors (StaticAligner, gyrocompassing) from sensor biases and white
// noise, to first order.
//
// The error is the small rotation delta (ENU axes) with q_estimated = exp(delta) * q_true:
// delta_E, delta_N are the tilt errors about east and north, delta_U the yaw error (estimated
// minus true yaw, REP-103: positive towards north from east, i.e. anticlockwise seen from above).
// With b the accelerometer bias and e the gyro bias projected to ENU (b_E = east component...):
//   delta_E =  b_N / g
//   delta_N = -b_E / g
//   delta_U =  e_E / (W cos L) - b_E tan L / g
// This is Golovach 2017 eq. 1.1 (Titterton & Weston's gyrocompassing limit) without its noise terms:
// the heading error in compass convention (clockwise) is -delta_U = b_E tan L / g - e_E / (W cos
// L); the relative sign of the two terms depends on how "bias" and "heading error" are signed, and
// budgets usually add magnitudes.
// White noise (angle random walk N_g in rad/sqrt(s), velocity random walk N_a in m/s/sqrt(s))
// averaged over T seconds adds zero-mean errors with covariance (alignment_noise_covariance_rad2):
//   var delta_E = var delta_N = N_a^2 / (g^2 T)
//   var delta_U = N_g^2 / (W^2 cos^2 L T) + tan^2 L N_a^2 / (g^2 T),
//   cov(delta_N, delta_U) = tan L N_a^2 / (g^2 T)   (both come from b_E).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace imu_lab {
namespace nav {

Eigen::Vector3d predicted_alignment_error_rad(const Eigen::Vector3d& gyro_bias_body_rad_s,
                                              const Eigen::Vector3d& accel_bias_body_m_s2,
                                              const Eigen::Quaterniond& q_body_to_enu, double latitude_rad,
                                              double gravity_m_s2, double earth_rate_rad_s);

Eigen::Matrix3d alignment_noise_covariance_rad2(double gyro_angle_random_walk_rad_per_sqrt_s,
                                                double accel_velocity_random_walk_m_s_per_sqrt_s, double duration_s,
                                                double latitude_rad, double gravity_m_s2, double earth_rate_rad_s);

}  // namespace nav
}  // namespace imu_lab
