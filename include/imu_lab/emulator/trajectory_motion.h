// A level trajectory over the Earth (see TrajectoryConfig). Speed, yaw, ENU velocity and its
// derivative are closed-form in each leg; latitude and longitude follow
//   dlat/dt = v_N / (M + h),  dlon/dt = v_E / ((N + h) cos lat)
// integrated by RK4 between nodes at most 0.25 s apart (and at every leg boundary), kept as the
// run goes; truth_at(t) takes one RK4 step from the node before t. With turn rates up to
// 0.1 rad/s the local error is ~1e-17 rad per node: far below anything the sensor can see.
// Not for polar paths (cos lat in the longitude rate).
#pragma once

#include <vector>

#include "imu_lab/emulator/kinematic_motion.h"
#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

class TrajectoryMotion : public KinematicMotion {
 public:
  explicit TrajectoryMotion(const ScenarioConfig& scenario);
  TruthState truth_at(double time_s) const override;

 protected:
  const std::vector<double>& breakpoints_s() const override { return leg_starts_s_; }
  double longest_smooth_piece_s() const override { return longest_piece_s_; }

 private:
  struct Leg {
    double start_s = 0.0;
    double duration_s = 0.0;  // the last leg is open-ended
    double start_speed_m_s = 0.0;
    double start_yaw_rad = 0.0;
    double acceleration_m_s2 = 0.0;
    double yaw_rate_rad_s = 0.0;
  };
  struct PositionNode {
    double time_s = 0.0;
    std::size_t leg = 0;
    double latitude_rad = 0.0;
    double longitude_rad = 0.0;
  };

  std::size_t leg_index(double time_s) const;
  Eigen::Vector3d velocity_enu_m_s(const Leg& leg, double time_s) const;
  PositionNode position_step(const PositionNode& from, double to_s) const;
  const PositionNode& node_before(double time_s) const;

  ScenarioConfig scenario_;
  std::vector<Leg> legs_;
  std::vector<double> leg_starts_s_;
  double longest_piece_s_ = 1.0;
  mutable std::vector<PositionNode> nodes_;  // grows as later times are asked for
};

}  // namespace emulator
}  // namespace imu_lab
