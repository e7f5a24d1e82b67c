#include "imu_lab/nav/rotation.h"

#include <cmath>

namespace imu_lab {
namespace nav {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(),  //
      v.z(), 0.0, -v.x(),   //
      -v.y(), v.x(), 0.0;
  return m;
}

Eigen::Quaterniond quaternion_from_rotation_vector(const Eigen::Vector3d& rotation_vector_rad) {
  const double angle = rotation_vector_rad.norm();
  // sin(angle/2)/angle is 0/0 at zero: use its series where the direct form loses digits.
  const double sin_half_over_angle = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(0.5 * angle) / angle;
  const Eigen::Vector3d vector_part = sin_half_over_angle * rotation_vector_rad;
  return Eigen::Quaterniond(std::cos(0.5 * angle), vector_part.x(), vector_part.y(), vector_part.z());
}

Eigen::Vector3d rotation_vector_from_quaternion(const Eigen::Quaterniond& rotation) {
  Eigen::Quaterniond q = rotation.normalized();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // q and -q are the same rotation; take angle <= pi
  const double sin_half = q.vec().norm();
  if (sin_half < 1e-12) return 2.0 * q.vec() / q.w();
  const double angle = 2.0 * std::atan2(sin_half, q.w());
  return q.vec() * (angle / sin_half);
}

Eigen::Quaterniond propagate_attitude(const Eigen::Quaterniond& q_body_to_nav,
                                      const Eigen::Vector3d& body_rotation_vector_rad,
                                      const Eigen::Vector3d& nav_rotation_vector_rad) {
  // C(k) = C_{n(k-1)}^{n(k)} C(k-1) C_{b(k)}^{b(k-1)}; the nav frame turning by +zeta moves
  // fixed vectors' coordinates by -zeta.
  Eigen::Quaterniond updated = quaternion_from_rotation_vector(-nav_rotation_vector_rad) * q_body_to_nav *
                               quaternion_from_rotation_vector(body_rotation_vector_rad);
  updated.normalize();
  return updated;
}

}  // namespace nav
}  // namespace imu_lab
