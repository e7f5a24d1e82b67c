// A motion whose truth is known in closed form at every instant (truth_at). Its increments are
// the integrals of that truth's body rate and specific force, by 8-point Gauss-Legendre on the
// smooth pieces between the motion's breakpoints (piecewise_quadrature.h): exact to round-off,
// so sample k's increment does not depend on how the run is cut into samples.
#pragma once

#include <vector>

#include "imu_lab/emulator/motion_source.h"
#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

class KinematicMotion : public MotionSource {
 public:
  TruthIncrement increment(double start_s, double interval_s) override;

 protected:
  // Sorted instants where the rate or force (or their derivatives) jump, e.g. the start of a
  // table's acceleration. Only those within the interval matter.
  virtual const std::vector<double>& breakpoints_s() const = 0;
  // Longest piece one quadrature covers: short enough that the fastest oscillation or rotation
  // of the truth turns by at most ~1 rad across it.
  virtual double longest_smooth_piece_s() const = 0;
};

// A smooth oscillation at the scenario's site (coning, sculling): no breakpoints, and pieces
// of at most 1 rad of its phase.
class SmoothPeriodicMotion : public KinematicMotion {
 protected:
  SmoothPeriodicMotion(const ScenarioConfig& scenario, double frequency_hz);
  const std::vector<double>& breakpoints_s() const override { return no_breakpoints_; }
  double longest_smooth_piece_s() const override { return longest_piece_s_; }

  ScenarioConfig scenario_;

 private:
  std::vector<double> no_breakpoints_;
  double longest_piece_s_ = 1.0;
};

}  // namespace emulator
}  // namespace imu_lab
