#include "imu_lab/allan/streaming_difference_accumulator.h"

#include <utility>

namespace imu_lab {
namespace allan {

DifferenceAccumulator::DifferenceAccumulator(int order, std::vector<int> averaging_factors)
    : order_(order),
      averaging_factors_(std::move(averaging_factors)),
      open_segment_overlapping_(averaging_factors_.size()),
      closed_overlapping_(averaging_factors_.size()),
      non_overlapping_(averaging_factors_.size()),
      closed_spread_(averaging_factors_.size()),
      next_non_overlapping_end_(averaging_factors_.size()) {
  start_segment();
}

namespace {

double spread(const DifferenceSums& sums) {
  return sums.count > 0 ? sums.squares.value() - sums.values.value() * sums.mean() : 0.0;
}

}  // namespace

DifferenceSums DifferenceAccumulator::overlapping(std::size_t tau_index) const {
  DifferenceSums pooled = closed_overlapping_[tau_index];
  pooled.merge(open_segment_overlapping_[tau_index]);
  return pooled;
}

double DifferenceAccumulator::overlapping_spread(std::size_t tau_index) const {
  return closed_spread_[tau_index].value() + spread(open_segment_overlapping_[tau_index]);
}

void DifferenceAccumulator::start_segment() {
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    closed_spread_[i].add(spread(open_segment_overlapping_[i]));
    closed_overlapping_[i].merge(open_segment_overlapping_[i]);
    open_segment_overlapping_[i] = DifferenceSums();
    next_non_overlapping_end_[i] = static_cast<std::int64_t>(order_) * averaging_factors_[i];
  }
}

void DifferenceAccumulator::update(const PhaseRing& ring) {
  const std::int64_t newest = ring.newest();
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    const int m = averaging_factors_[i];
    // Factors ascend, so once one lacks history all the larger ones do too.
    if (newest < static_cast<std::int64_t>(order_) * m) break;
    const double difference = phase_difference(ring, newest, m, order_);
    open_segment_overlapping_[i].add(difference);
    if (newest == next_non_overlapping_end_[i]) {
      non_overlapping_[i].add(difference);
      next_non_overlapping_end_[i] += m;
    }
  }
}

std::size_t DifferenceAccumulator::heap_bytes() const {
  return averaging_factors_.capacity() * sizeof(int) +
         (open_segment_overlapping_.capacity() + closed_overlapping_.capacity() + non_overlapping_.capacity()) *
             sizeof(DifferenceSums) +
         closed_spread_.capacity() * sizeof(CompensatedSum) +
         next_non_overlapping_end_.capacity() * sizeof(std::int64_t);
}

void DifferenceAccumulator::save(BinaryWriter& out) const {
  out.put_u64(averaging_factors_.size());
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    closed_overlapping_[i].save(out);
    non_overlapping_[i].save(out);
    open_segment_overlapping_[i].save(out);
    closed_spread_[i].save(out);
  }
  out.put_i64s(next_non_overlapping_end_);
}

void DifferenceAccumulator::load(BinaryReader& in) {
  in.expect_u64(averaging_factors_.size(), "number of averaging factors");
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    closed_overlapping_[i].load(in);
    non_overlapping_[i].load(in);
    open_segment_overlapping_[i].load(in);
    closed_spread_[i].load(in);
  }
  next_non_overlapping_end_ = in.get_i64s();
  if (next_non_overlapping_end_.size() != averaging_factors_.size()) in.fail("averaging factor count");
}

}  // namespace allan
}  // namespace imu_lab
