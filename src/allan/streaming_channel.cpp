#include "imu_lab/allan/streaming_channel.h"

#include <cmath>
#include <string>

namespace imu_lab {
namespace allan {

ChannelAccumulator::ChannelAccumulator(const TauPlan& plan, double offset, std::size_t history_capacity)
    : offset_(offset), history_(history_capacity) {
  levels_.reserve(plan.levels.size());
  for (const PlannedLevel& planned : plan.levels) levels_.emplace_back(planned.level, planned.level_averaging_factors);
  history_.push(0.0);
}

void ChannelAccumulator::push(double value) {
  phase_.add(value - offset_);
  ++segment_sample_count_;
  const double phase = phase_.value();
  history_.push(phase);
  for (ResolutionLevel& level : levels_) {
    const std::int64_t block_mask = (std::int64_t{1} << level.level()) - 1;
    // Sub-sampling the phase every 2^L samples is averaging the rate over blocks of 2^L;
    // dividing by 2^L (exact, and no libm call per sample) expresses it in samples of that
    // level. Levels ascend, so the first that skips this sample has every higher one skip it too.
    if ((segment_sample_count_ & block_mask) != 0) break;
    level.append_phase(phase * level.phase_scale());
  }
}

void ChannelAccumulator::flush() {
  for (ResolutionLevel& level : levels_) level.process_appended();
}

bool ChannelAccumulator::has_unprocessed_points() const {
  for (const ResolutionLevel& level : levels_) {
    if (level.has_unprocessed_points()) return true;
  }
  return false;
}

void ChannelAccumulator::break_segment() {
  if (segment_sample_count_ == 0) return;
  phase_ = CompensatedSum();
  segment_sample_count_ = 0;
  for (ResolutionLevel& level : levels_) level.restart_segment();
  history_.start_segment();
  history_.push(0.0);
}

std::size_t ChannelAccumulator::heap_bytes() const {
  std::size_t bytes = levels_.capacity() * sizeof(ResolutionLevel);
  for (const ResolutionLevel& level : levels_) bytes += level.heap_bytes();
  return bytes + history_.heap_bytes();
}

void ChannelAccumulator::save(BinaryWriter& out) const {
  out.put_f64(offset_);
  phase_.save(out);
  out.put_i64(segment_sample_count_);
  out.put_u64(levels_.size());
  for (const ResolutionLevel& level : levels_) level.save(out);
  history_.save(out);
}

void ChannelAccumulator::load(BinaryReader& in) {
  offset_ = in.get_finite_f64();
  phase_.load(in);
  segment_sample_count_ = in.get_count();
  in.expect_u64(levels_.size(), "number of pyramid levels");
  for (ResolutionLevel& level : levels_) {
    level.load(in);
    // push(): level L holds the segment's point 0 and one point per 2^L samples.
    if (level.phase_count() != (segment_sample_count_ >> level.level()) + 1) {
      in.fail("pyramid level " + std::to_string(level.level()) + " out of step with the segment's sample count");
    }
  }
  history_.load(in);
  if (history_.open_segment_count() != segment_sample_count_ + 1) {
    in.fail("phase history out of step with the segment's sample count");
  }
}

}  // namespace allan
}  // namespace imu_lab
