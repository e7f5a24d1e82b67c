// The YAML summary of an Allan run (allan_summary.yaml): where the samples came from, the sample
// period tau0 estimated from the stamps and its jitter, every stamp and value irregularity with
// what the policy did about it, the impulse screen's events (knocks, spikes) and the level-shift
// screen's steps with their stamps,
// and per channel the offset, the output's step (LSB) and the minimum OADEV with its tau.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "imu_lab/allan/impulse_screen.h"
#include "imu_lab/allan/level_shift_screen.h"
#include "imu_lab/allan/output_step.h"
#include "imu_lab/allan/streaming_allan.h"
#include "imu_lab/io/recording_window.h"
#include "imu_lab/pipeline/allan_samples.h"
#include "imu_lab/pipeline/allan_warm_up.h"

namespace imu_lab {
namespace pipeline {

struct AllanRunDescription {
  std::string bag;                  // the bag read; empty for a live topic
  std::vector<std::string> files;   // a split recording's files in the order read (several only)
  io::TimeWindow window;            // the part of the bag analysed
  std::vector<io::FileJoin> joins;  // where the split files hand over
  std::string topic;                // the topic read or subscribed to
  AllanInput input = AllanInput::kRate;
  allan::StreamingOptions engine;
  std::int64_t skipped_before_checkpoint = 0;          // live only: replayed samples a resumed node skipped
  allan::ImpulseScreenReport impulses;                 // the screen before the engine
  allan::LevelShiftReport level_shifts;                // the screen after it, before the engine
  std::vector<allan::ChannelOutputStep> output_steps;  // per channel (empty: not watched)
  std::optional<AllanWarmUp> warm_up;                  // the transients removed first (allan --remove-warm-up)
};

std::string format_allan_summary(const AllanRunDescription& run, const allan::StreamingSnapshot& snapshot);

// The engine's gaps that the impulse screen made by leaving a knock's samples out (the engine
// sees the hole as a gap and splits the run there; impulse_screen.h), and their time (interval -
// tau0 each): a gap whose interval holds dropped windows, and which would be no gap with their
// samples back, is the screen's (an input gap inside a dropped window is taken with it). Only
// the engine's listed stamp events
// (allan::kMaxRecordedStampEvents) can be matched: gaps past them are counted as the input's.
struct ScreenMadeGaps {
  std::int64_t count = 0;
  double time_s = 0.0;
};
ScreenMadeGaps impulse_screen_gaps(const allan::TimingReport& timing, const allan::ImpulseScreenReport& screen,
                                   double gap_factor);

// Lines (each starting with `prefix`) for a person: the screen's verdict and one line per listed
// event, its stamps from the input's first stamp and absolute, its channels and peaks.
std::string format_impulse_events(const std::string& prefix, const allan::ImpulseScreenReport& screen);
// The same for the level-shift screen: one line per listed shift, its step and sizes.
std::string format_level_shifts(const std::string& prefix, AllanInput input, const allan::LevelShiftReport& screen);
// "gyro_x 0.000872664626 rad_s, ..., accel_z none" (none: not quantised).
std::string format_output_steps(AllanInput input, const std::vector<allan::ChannelOutputStep>& steps);

// The smallest deviation of a curve (nullptr for an empty curve).
const allan::StabilityPoint* minimum_point(const std::vector<allan::StabilityPoint>& curve);

}  // namespace pipeline
}  // namespace imu_lab
