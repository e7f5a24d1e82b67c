// Puts any motion into a thermal profile: the motion's truth with the profile's temperatures
// (sensor, its rate of change, and the second thermosensor when configured).
#pragma once

#include <memory>

#include "imu_lab/emulator/motion_source.h"
#include "imu_lab/emulator/thermal_profile.h"

namespace imu_lab {
namespace emulator {

class ThermalMotion : public MotionSource {
 public:
  ThermalMotion(std::unique_ptr<MotionSource> motion, const ThermalConfig& thermal);
  // Mean temperatures by Gauss-Legendre between the segment starts (exact to round-off); the
  // mean rate of change is (T(end) - T(start)) / interval, exact.
  TruthIncrement increment(double start_s, double interval_s) override;
  TruthState truth_at(double time_s) const override;

 private:
  std::unique_ptr<MotionSource> motion_;
  ThermalProfile profile_;
  double longest_piece_s_ = 1.0;
};

}  // namespace emulator
}  // namespace imu_lab
