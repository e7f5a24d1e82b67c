#include "imu_lab/allan/streaming_level.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "imu_lab/allan/streaming_total_ends.h"

namespace imu_lab {
namespace allan {
namespace {

constexpr int kAllanOrder = 2;
constexpr int kHadamardOrder = 3;

constexpr std::int64_t kMaxRunPhasePoints = std::int64_t{1} << 53;

int largest(const std::vector<int>& ascending) { return ascending.empty() ? 1 : ascending.back(); }

}  // namespace

ResolutionLevel::ResolutionLevel(int level, std::vector<int> averaging_factors)
    : level_(level),
      phase_scale_(std::ldexp(1.0, -level)),
      averaging_factors_(std::move(averaging_factors)),
      head_capacity_(2 * static_cast<std::size_t>(largest(averaging_factors_))),
      // Hadamard and modified Allan reach back 3m points.
      ring_(3 * static_cast<std::size_t>(largest(averaging_factors_)) + 1, phase_block_points(level)),
      allan_(kAllanOrder, averaging_factors_),
      hadamard_(kHadamardOrder, averaging_factors_),
      modified_(averaging_factors_),
      block_autocorrelation_(averaging_factors_),
      closed_total_end_terms_(averaging_factors_.size()) {
  head_.reserve(head_capacity_);
  append_phase(0.0);
}

void ResolutionLevel::append_phase(double phase) {
  if (ring_.full()) process_appended();
  ring_.push(phase);
  if (head_.size() < head_capacity_) head_.push_back(phase);
}

void ResolutionLevel::process_appended() {
  if (processed_count_ == ring_.count()) return;
  allan_.update(ring_, processed_count_);
  hadamard_.update(ring_, processed_count_);
  modified_.update(ring_, processed_count_);
  block_autocorrelation_.update(ring_);
  processed_count_ = ring_.count();
}

void ResolutionLevel::restart_segment() {
  process_appended();
  if (open_segment_has_data()) {
    for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
      const int m = averaging_factors_[i];
      if (ring_.count() >= 2 * static_cast<std::int64_t>(m) + 1) {
        closed_total_end_terms_[i].add(total_end_terms(head_, ring_, m));
      }
    }
    ++closed_segment_phase_counts_[ring_.count()];
  }
  ring_.clear();
  processed_count_ = 0;
  head_.clear();
  allan_.start_segment();
  hadamard_.start_segment();
  modified_.start_segment();
  block_autocorrelation_.start_segment();
  append_phase(0.0);
}

double ResolutionLevel::total_end_terms_sum(std::size_t tau_index) const {
  double sum = closed_total_end_terms_[tau_index].value();
  const int m = averaging_factors_[tau_index];
  if (ring_.count() >= 2 * static_cast<std::int64_t>(m) + 1) sum += total_end_terms(head_, ring_, m);
  return sum;
}

std::map<std::int64_t, std::int64_t> ResolutionLevel::segment_phase_counts() const {
  std::map<std::int64_t, std::int64_t> counts = closed_segment_phase_counts_;
  if (open_segment_has_data()) ++counts[ring_.count()];
  return counts;
}

std::size_t ResolutionLevel::heap_bytes() const {
  // A map node holds the pair plus about four pointers of bookkeeping.
  const std::size_t map_node_bytes = 2 * sizeof(std::int64_t) + 4 * sizeof(void*);
  return averaging_factors_.capacity() * sizeof(int) + ring_.heap_bytes() + head_.capacity() * sizeof(double) +
         allan_.heap_bytes() + hadamard_.heap_bytes() + modified_.heap_bytes() + block_autocorrelation_.heap_bytes() +
         closed_total_end_terms_.capacity() * sizeof(CompensatedSum) +
         closed_segment_phase_counts_.size() * map_node_bytes;
}

void ResolutionLevel::save(BinaryWriter& out) const {
  out.put_i64(level_);
  out.put_u64(averaging_factors_.size());
  ring_.save(out);
  out.put_i64(processed_count_);
  out.put_f64s(head_);
  allan_.save(out);
  hadamard_.save(out);
  modified_.save(out);
  block_autocorrelation_.save(out);
  for (const CompensatedSum& sum : closed_total_end_terms_) sum.save(out);
  out.put_u64(closed_segment_phase_counts_.size());
  for (const auto& entry : closed_segment_phase_counts_) {
    out.put_i64(entry.first);
    out.put_i64(entry.second);
  }
}

void ResolutionLevel::load(BinaryReader& in) {
  in.expect_u64(static_cast<std::uint64_t>(level_), "pyramid level");
  in.expect_u64(averaging_factors_.size(), "number of averaging factors");
  ring_.load(in);
  // A segment starts with its phase point 0 (restart_segment), so the ring is never empty.
  if (ring_.count() < 1) in.fail("empty phase window");
  processed_count_ = in.get_i64();
  if (processed_count_ < 0 || processed_count_ > ring_.count()) in.fail("processed point count out of range");
  // The accumulators reach back up to history() - 1 points before the first unprocessed point.
  if (ring_.oldest_stored() > 0 &&
      processed_count_ - static_cast<std::int64_t>(ring_.history()) + 1 < ring_.oldest_stored()) {
    in.fail("unprocessed phase points without the history before them");
  }
  head_ = in.get_finite_f64s();
  if (head_.size() != std::min(static_cast<std::size_t>(ring_.count()), head_capacity_)) {
    in.fail("segment head of another length than the segment");
  }
  head_.reserve(head_capacity_);
  allan_.load(in, processed_count_);
  hadamard_.load(in, processed_count_);
  modified_.load(in);
  block_autocorrelation_.load(in, processed_count_);
  for (CompensatedSum& sum : closed_total_end_terms_) sum.load(in);
  closed_segment_phase_counts_.clear();
  const std::uint64_t entries = in.get_u64();
  std::int64_t closed_phase_points = 0;
  for (std::uint64_t i = 0; i < entries; ++i) {
    const std::int64_t phase_count = in.get_i64();
    const std::int64_t segment_count = in.get_i64();
    // Only segments with data (two phase points or more) are closed into the map, and no run
    // reaches 2^53 points (285 years at 1 MHz): the statistics' normalisers stay exact integers.
    std::int64_t points = 0;
    if (phase_count < 2 || segment_count < 1 || __builtin_mul_overflow(phase_count, segment_count, &points) ||
        __builtin_add_overflow(closed_phase_points, points, &closed_phase_points) ||
        closed_phase_points > kMaxRunPhasePoints) {
      in.fail("closed segment length or count out of range");
    }
    closed_segment_phase_counts_[phase_count] = segment_count;
  }
}

}  // namespace allan
}  // namespace imu_lab
