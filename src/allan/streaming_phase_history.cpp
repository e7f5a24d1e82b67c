#include "imu_lab/allan/streaming_phase_history.h"

#include <cmath>
#include <utility>

namespace imu_lab {
namespace allan {

PhaseHistory::PhaseHistory(std::size_t capacity) : capacity_(capacity) { open_.phase.reserve(capacity_ + 1); }

void PhaseHistory::append(Segment& segment, double level0_phase) const {
  const std::int64_t block_mask = (std::int64_t{1} << segment.level) - 1;
  if ((segment.level0_count & block_mask) == 0) {
    // Times 2^-level, exact: ldexp's result without its libm call on every sample.
    segment.phase.push_back(level0_phase / static_cast<double>(std::int64_t{1} << segment.level));
  }
  ++segment.level0_count;
  if (segment.phase.size() <= capacity_) return;
  // Too long for B1 at this level: keep the next level (every other point, halved).
  std::size_t kept = 0;
  for (std::size_t i = 0; i < segment.phase.size(); i += 2) segment.phase[kept++] = 0.5 * segment.phase[i];
  segment.phase.resize(kept);
  ++segment.level;
}

void PhaseHistory::push(double level0_phase) { append(open_, level0_phase); }

void PhaseHistory::start_segment() {
  if (open_.level0_count > longest_closed_.level0_count) {
    longest_closed_.level = open_.level;
    longest_closed_.level0_count = open_.level0_count;
    longest_closed_.phase.assign(open_.phase.begin(), open_.phase.end());
  }
  open_.level = 0;
  open_.level0_count = 0;
  open_.phase.clear();
}

std::vector<double> PhaseHistory::phase_at_level(int level) const {
  const Segment& segment = open_.level0_count >= longest_closed_.level0_count ? open_ : longest_closed_;
  if (level < segment.level) return {};
  const std::size_t stride = std::size_t{1} << (level - segment.level);
  // Points up to the last complete block of this level only, as the level itself holds them.
  const std::size_t level_points = static_cast<std::size_t>((segment.level0_count - 1) >> level) + 1;
  // Times 2^(segment.level - level), exact: the same bits as ldexp without a libm call per point
  // (a power of two in range times a double is rounded once, as ldexp rounds).
  const double scale = std::ldexp(1.0, segment.level - level);
  std::vector<double> phase(level_points);
  for (std::size_t j = 0; j < level_points; ++j) phase[j] = segment.phase[j * stride] * scale;
  return phase;
}

std::size_t PhaseHistory::heap_bytes() const {
  return (open_.phase.capacity() + longest_closed_.phase.capacity()) * sizeof(double);
}

void PhaseHistory::save_segment(const Segment& segment, BinaryWriter& out) {
  out.put_i64(segment.level);
  out.put_i64(segment.level0_count);
  out.put_f64s(segment.phase);
}

void PhaseHistory::load_segment(Segment& segment, BinaryReader& in) const {
  segment.level = static_cast<int>(in.get_i64());
  segment.level0_count = in.get_i64();
  std::vector<double> phase = in.get_finite_f64s();
  if (phase.size() > capacity_ || segment.level < 0 || segment.level > 62 || segment.level0_count < 0) {
    in.fail("phase history out of shape");
  }
  // append() keeps level-0 points 0, 2^level, 2 * 2^level, ...: phase_at_level relies on the count.
  const std::int64_t kept_points = segment.level0_count == 0 ? 0 : ((segment.level0_count - 1) >> segment.level) + 1;
  if (static_cast<std::int64_t>(phase.size()) != kept_points) in.fail("phase history length does not match its count");
  segment.phase.assign(phase.begin(), phase.end());
}

void PhaseHistory::save(BinaryWriter& out) const {
  save_segment(open_, out);
  save_segment(longest_closed_, out);
}

void PhaseHistory::load(BinaryReader& in) {
  load_segment(open_, in);
  load_segment(longest_closed_, in);
}

}  // namespace allan
}  // namespace imu_lab
