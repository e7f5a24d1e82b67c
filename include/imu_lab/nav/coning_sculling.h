// Coning and sculling corrections for one IMU interval, in the two-sample form that pairs the
// current increment with the previous interval's (Savage, "Strapdown Inertial Navigation
// Integration Algorithm Design", JGCD 1998, parts 1-2; Ignagni 1990):
//   rotation vector   phi  = a + (1/12) a_prev x a                                  (coning)
//   velocity (body)   dv_b = v + (1/2) a x v + (1/12) (a_prev x v + v_prev x a)     (rotation
//                                                                            + sculling)
// a, v: delta angle and delta velocity of the interval; a_prev, v_prev: those of the previous one.
// Both terms assume true increments (integrals over the interval), see imu_increment.h, and
// intervals of equal length. dv_b is expressed in the body frame at the start of the interval.
// On the first interval (no previous one) the coning and sculling terms are zero.
#pragma once

#include <Eigen/Core>

#include "imu_lab/nav/imu_increment.h"

namespace imu_lab {
namespace nav {

struct ConingScullingConfig {
  bool coning_correction = true;
  bool sculling_correction = true;  // the (1/12) term; the (1/2) a x v rotation term is always on
};

struct CompensatedIncrement {
  Eigen::Vector3d rotation_vector_rad = Eigen::Vector3d::Zero();  // body(k) relative to body(k-1)
  Eigen::Vector3d delta_velocity_m_s = Eigen::Vector3d::Zero();   // in body(k-1) axes
};

class ConingScullingCompensator {
 public:
  explicit ConingScullingCompensator(const ConingScullingConfig& config = ConingScullingConfig());

  CompensatedIncrement compensate(const ImuIncrement& increment);

  // Forget the previous interval (after a gap in the data, or re-initialisation).
  void reset();

 private:
  ConingScullingConfig config_;
  Eigen::Vector3d previous_delta_angle_rad_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d previous_delta_velocity_m_s_ = Eigen::Vector3d::Zero();
};

}  // namespace nav
}  // namespace imu_lab
