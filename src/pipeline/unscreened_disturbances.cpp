#include "imu_lab/pipeline/unscreened_disturbances.h"

#include <cmath>

#include "imu_lab/common/format_number.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/pipeline/allan_samples.h"

namespace imu_lab {
namespace pipeline {
namespace {

// The allan tool's screens as it runs them (its defaults, its engine's gap factor).
allan::ImpulseScreenOptions impulse_options() {
  allan::ImpulseScreenOptions options;
  options.channel_count = kAllanChannelCount;
  options.gap_factor = allan::StreamingOptions().gap_factor;
  return options;
}

allan::LevelShiftScreenOptions level_shift_options() {
  allan::LevelShiftScreenOptions options;
  options.channel_count = kAllanChannelCount;
  options.gap_factor = allan::StreamingOptions().gap_factor;
  return options;
}

}  // namespace

DisturbanceFinder::DisturbanceFinder() : impulses_(impulse_options()), level_shifts_(level_shift_options()) {}

void DisturbanceFinder::push(const io::ImuRecord& record) {
  const AllanSample sample = to_allan_sample(record);
  impulses_.push(sample.stamp_ns, sample.values.data(), passed_);
  level_shifts_.push(passed_, unshifted_);
  passed_.clear();
  unshifted_.clear();
}

UnscreenedDisturbances DisturbanceFinder::finish() {
  impulses_.finish(passed_);
  level_shifts_.push(passed_, unshifted_);
  level_shifts_.finish(unshifted_);
  passed_.clear();
  unshifted_.clear();
  return {impulses_.report(), level_shifts_.report()};
}

std::string unscreened_disturbance_note(const std::string& tool, const UnscreenedDisturbances& found,
                                        const std::string& what) {
  if (!found.any()) return "";
  std::string text = tool + ": note: allan's screens find";
  const allan::ImpulseScreenReport& impulses = found.impulses;
  if (impulses.event_count > 0) {
    text += " " + std::to_string(impulses.event_count) + " knock(s) or spike(s)";
    if (!impulses.events.empty()) {
      const allan::ImpulseEvent* largest = &impulses.events.front();
      for (const allan::ImpulseEvent& event : impulses.events) {
        if (std::abs(event.peak_sigma) > std::abs(largest->peak_sigma)) largest = &event;
      }
      text += " (first at " +
              format_printf(seconds_between(impulses.first_stamp_ns, impulses.events.front().onset_stamp_ns), "%.1f") +
              " s from the start, largest " + format_printf(largest->peak_sigma, "%+.0f") + " scales in " +
              kAllanChannelNames[largest->peak_channel] + " at " +
              format_printf(seconds_between(impulses.first_stamp_ns, largest->peak_stamp_ns), "%.1f") + " s)";
    }
  }
  const allan::LevelShiftReport& shifts = found.level_shifts;
  if (shifts.event_count > 0) {
    text +=
        std::string(impulses.event_count > 0 ? " and " : " ") + std::to_string(shifts.event_count) + " level shift(s)";
    if (!shifts.events.empty()) {
      const allan::LevelShiftEvent& first = shifts.events.front();
      text += " (first at " + format_printf(seconds_between(impulses.first_stamp_ns, first.step_stamp_ns), "%.1f") +
              " s, in " + kAllanChannelNames[first.peak_channel] + ")";
    }
  }
  return text + ". They are in " + what +
         "; allan leaves their samples out and splits the record there, so its curves lie lower where they "
         "matter (allan --no-impulse-screen --no-level-shift-screen keeps them, as here; doc/impulse_screen.md)\n";
}

}  // namespace pipeline
}  // namespace imu_lab
