// Classical coning at a fixed site (see ConingConfig). Closed form, with a = half-angle and
// W = 2 pi f:  q(t) = [cos(a/2), sin(a/2) cos(W t), sin(a/2) sin(W t), 0]  (body -> mount) and the
// body rate w.r.t. the mount  w(t) = (-W sin a sin(W t), W sin a cos(W t), -2 W sin^2(a/2)),
// from w = 2 vec(q* (x) dq/dt). The truth adds the Earth rate through the attitude.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "imu_lab/emulator/kinematic_motion.h"
#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

Eigen::Quaterniond coning_attitude_body_to_mount(double half_angle_rad, double frequency_hz, double time_s);
Eigen::Vector3d coning_rate_body_wrt_mount_rad_s(double half_angle_rad, double frequency_hz, double time_s);

class ConingMotion : public SmoothPeriodicMotion {
 public:
  explicit ConingMotion(const ScenarioConfig& scenario);
  TruthState truth_at(double time_s) const override;

 private:
  ConingConfig coning_;
};

}  // namespace emulator
}  // namespace imu_lab
