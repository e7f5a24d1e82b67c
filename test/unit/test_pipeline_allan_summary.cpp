// The gaps an Allan run reports as the input's (pipeline/allan_summary.h): the holes the impulse
// screen leaves where it took a knock out are gaps to the engine, not in the recording, while a
// real gap next to a knock stays one.
#include <gtest/gtest.h>

#include "imu_lab/pipeline/allan_summary.h"

namespace imu_lab {
namespace pipeline {
namespace {

constexpr std::int64_t kTau0_ns = 10'000'000;  // 100 Hz

allan::StampEvent gap_event(std::int64_t previous_sample, std::int64_t sample) {
  allan::StampEvent gap;
  gap.kind = allan::StampEventKind::kGap;
  gap.sample_index = sample;
  gap.previous_stamp_ns = previous_sample * kTau0_ns;
  gap.stamp_ns = sample * kTau0_ns;
  return gap;
}

allan::ImpulseEvent window(std::int64_t first_sample, std::int64_t last_sample) {
  allan::ImpulseEvent event;
  event.start_stamp_ns = first_sample * kTau0_ns;
  event.end_stamp_ns = last_sample * kTau0_ns;
  event.dropped_sample_count = last_sample - first_sample + 1;
  return event;
}

TEST(AllanSummary, GapsTheImpulseScreenMadeAreNotTheInputs) {
  allan::TimingReport timing;
  timing.tau0_s = 0.01;
  // 1: samples 1000-1314 dropped by the screen, the stamps regular around them.
  // 2: samples 5000-5125 dropped, and the input itself jumps from 5125 to 5400 (a real gap).
  // 3: a gap of the input alone.
  timing.events = {gap_event(999, 1315), gap_event(4999, 5400), gap_event(7000, 7300)};
  timing.gap_count = 3;
  allan::ImpulseScreenReport screen;
  screen.events = {window(1000, 1314), window(5000, 5125)};

  const ScreenMadeGaps made = impulse_screen_gaps(timing, screen, 1.5);
  EXPECT_EQ(made.count, 1);
  EXPECT_NEAR(made.time_s, 315 * 0.01, 1e-9);  // the interval 3.16 s less one tau0

  // Without the screen's windows every gap is the input's.
  EXPECT_EQ(impulse_screen_gaps(timing, allan::ImpulseScreenReport(), 1.5).count, 0);
}

}  // namespace
}  // namespace pipeline
}  // namespace imu_lab
