// Sculling at a fixed site (see ScullingConfig): the body rocks about one of its axes,
// angle(t) = A sin(W t), attitude = mount * Rot(rotation axis, angle), while the table point
// vibrates along a mount axis u (fixed in ENU): d(t) = D sin(W t + phase) u, with velocity and
// acceleration its exact derivatives. The reported position is the site moved by d, converted
// with the site's radii of curvature (d is millimetres: the neglected terms are ~(d/R)^2).
#pragma once

#include "imu_lab/emulator/kinematic_motion.h"
#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

class ScullingMotion : public SmoothPeriodicMotion {
 public:
  explicit ScullingMotion(const ScenarioConfig& scenario);
  TruthState truth_at(double time_s) const override;

 private:
  ScullingConfig sculling_;
  Eigen::Vector3d vibration_enu_ = Eigen::Vector3d::Zero();
};

}  // namespace emulator
}  // namespace imu_lab
