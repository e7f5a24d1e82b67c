// Static scenario: the body rests on the Earth in a fixed orientation; it senses the Earth rate
// and the reaction to normal gravity, both constant in body axes, so the increments are exact.
#pragma once

#include "imu_lab/emulator/motion_source.h"
#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

// Rz(yaw) * Ry(pitch) * Rx(roll): body -> ENU.
Eigen::Quaterniond attitude_from_roll_pitch_yaw(double roll_rad, double pitch_rad, double yaw_rad);

class StaticMotionSource : public MotionSource {
 public:
  explicit StaticMotionSource(const ScenarioConfig& scenario);
  TruthIncrement increment(double start_s, double interval_s) override;
  TruthState truth_at(double time_s) const override;

 private:
  TruthState state_;
};

}  // namespace emulator
}  // namespace imu_lab
