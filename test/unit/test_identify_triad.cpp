// Per-axis and per-triad identification: three axes of one emulated triad, the worst flagged.
#include <gtest/gtest.h>

#include <cmath>

#include "identify_test_records.h"
#include "imu_lab/identify/triad_fit.h"

namespace imu_lab {
namespace identify {
namespace {

TEST(IdentifyTriad, FitsEachAxisAndFlagsTheNoisiest) {
  constexpr double kRateHz = 100.0, kDurationS = 1800.0;
  const std::array<double, 3> white = {1e-4, 3e-4, 1.5e-4};
  emulator::TriadErrorModel model;
  for (int axis = 0; axis < 3; ++axis) {
    model.noise_per_axis[axis] = {noise::WhiteRateParameters{white[axis]}, noise::RandomWalkParameters{2e-6}};
  }
  const auto rates = identify_test::emulate_triad_rates(model, kRateHz, kDurationS, 9);
  std::array<std::vector<allan::StabilityPoint>, 3> curves;
  for (int axis = 0; axis < 3; ++axis) {
    curves[axis] = identify_test::octave_oadev(rates[axis], kRateHz);
  }
  const TriadFit triad = fit_triad(SensorKind::kGyroscope, curves, 1.0 / kRateHz, kDurationS);
  EXPECT_EQ(triad.worst_axis, 1);
  EXPECT_FALSE(triad.worst_axis_reason.empty());
  EXPECT_EQ(axis_name(SensorKind::kGyroscope, triad.worst_axis), "gyro_y");
  for (int axis = 0; axis < 3; ++axis) {
    const TermEstimate* n = triad.axes[axis].find("white_rate");
    ASSERT_NE(n, nullptr);
    EXPECT_LT(std::abs(n->amplitude.value - white[axis]), 3.0 * n->amplitude.sigma) << axis;
  }
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
