// Rotation-vector <-> quaternion maps and the attitude update built on them.
//
// Quaternions are Eigen's Hamilton quaternions; q_a_to_b rotates a vector's coordinates from
// frame a to frame b: v_b = q_a_to_b * v_a.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace imu_lab {
namespace nav {

// Matrix of the cross product: skew(a) * b == a.cross(b).
Eigen::Matrix3d skew(const Eigen::Vector3d& vector);

// Exact (not small-angle) quaternion of a rotation through |r| about r / |r|.
Eigen::Quaterniond quaternion_from_rotation_vector(const Eigen::Vector3d& rotation_vector_rad);

// Inverse of the above; returns the rotation vector of angle in [0, pi].
Eigen::Vector3d rotation_vector_from_quaternion(const Eigen::Quaterniond& rotation);

// One attitude step of a body->nav quaternion: the body turned by body_rotation_vector_rad
// (coning-compensated, in the body frame at the interval start) while the nav frame turned by
// nav_rotation_vector_rad (in nav axes) relative to inertial space. Result is normalised.
Eigen::Quaterniond propagate_attitude(const Eigen::Quaterniond& q_body_to_nav,
                                      const Eigen::Vector3d& body_rotation_vector_rad,
                                      const Eigen::Vector3d& nav_rotation_vector_rad);

}  // namespace nav
}  // namespace imu_lab
