#include "imu_lab/allan/streaming_difference_accumulator.h"

#include <algorithm>
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

namespace {

// LaneVector helpers are inlined into the block loops: no vector crosses a call (see
// streaming_block_sums.h on -Wpsabi). Off to the end of this file, where GCC reports it.
#pragma GCC diagnostic ignored "-Wpsabi"

// The order-`Order` differences at lag m ending at x[0] .. x[3] (x[-j m] are the earlier
// points): the same operations in the same order as phase_difference, so the same bits.
template <int Order>
inline LaneVector differences_ending_at(const double* x, std::ptrdiff_t m) {
  if (Order == 2) return load_lanes(x) - 2.0 * load_lanes(x - m) + load_lanes(x - 2 * m);
  return load_lanes(x) - 3.0 * load_lanes(x - m) + 3.0 * load_lanes(x - 2 * m) - load_lanes(x - 3 * m);
}

template <int Order>
inline double difference_ending_at(const double* x, std::ptrdiff_t m) {
  if (Order == 2) return x[0] - 2.0 * x[-m] + x[-2 * m];
  return x[0] - 3.0 * x[-m] + 3.0 * x[-2 * m] - x[-3 * m];
}

template <int Order>
inline void add_overlapping(const double* x, std::int64_t count, std::ptrdiff_t m, BlockSums& sums) {
  std::int64_t k = 0;
  for (; k + BlockSums::kLanes <= count; k += BlockSums::kLanes) sums.add(differences_ending_at<Order>(x + k, m));
  for (; k < count; ++k) sums.add(0, difference_ending_at<Order>(x + k, m));
  sums.count += count;
}

// Overlapping differences ending at x[0] .. x[count - 1]. The lanes are summed in a local so
// they stay in registers.
IMU_LAB_ALLAN_BLOCK_LOOP
void sum_overlapping(const double* x, std::int64_t count, std::ptrdiff_t m, int order, BlockSums& out) {
  BlockSums sums;
  if (order == 2) {
    add_overlapping<2>(x, count, m, sums);
  } else {
    add_overlapping<3>(x, count, m, sums);
  }
  out = sums;
}

// Non-overlapping differences ending at x[0], x[m], ... (count of them): one in m points, so
// a plain strided loop.
void sum_non_overlapping(const double* x, std::int64_t count, std::ptrdiff_t m, int order, BlockSums& out) {
  BlockSums sums;
  for (std::int64_t k = 0; k < count; ++k, x += m) {
    sums.add(0, order == 2 ? difference_ending_at<2>(x, m) : difference_ending_at<3>(x, m));
  }
  sums.count = count;
  out = sums;
}

}  // namespace

void DifferenceAccumulator::update(const PhaseRing& ring, std::int64_t first_index) {
  const std::int64_t newest = ring.newest();
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    const int m = averaging_factors_[i];
    // Factors ascend, so once one lacks history all the larger ones do too.
    const std::int64_t first_term = std::max(first_index, static_cast<std::int64_t>(order_) * m);
    if (first_term > newest) break;
    // A few points (push() of one sample) cost less as per-term compensated sums than as a block.
    const std::int64_t count = newest - first_term + 1;
    DifferenceSums& overlapping = open_segment_overlapping_[i];
    if (count < BlockSums::kLanes) {
      for (std::int64_t n = first_term; n <= newest; ++n) overlapping.add(phase_difference(ring, n, m, order_));
    } else {
      BlockSums block;
      sum_overlapping(ring.point(first_term), count, m, order_, block);
      overlapping.add_block(block);
    }
    std::int64_t& end = next_non_overlapping_end_[i];
    const std::int64_t ends = end <= newest ? (newest - end) / m + 1 : 0;
    if (ends < BlockSums::kLanes) {
      for (; end <= newest; end += m) non_overlapping_[i].add(phase_difference(ring, end, m, order_));
    } else {
      BlockSums block;
      sum_non_overlapping(ring.point(end), ends, m, order_, block);
      non_overlapping_[i].add_block(block);
      end += ends * m;
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

void DifferenceAccumulator::load(BinaryReader& in, std::int64_t processed_count) {
  in.expect_u64(averaging_factors_.size(), "number of averaging factors");
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    closed_overlapping_[i].load(in);
    non_overlapping_[i].load(in);
    open_segment_overlapping_[i].load(in);
    closed_spread_[i].load(in);
  }
  next_non_overlapping_end_ =
      load_next_block_ends(in, order_, averaging_factors_, processed_count, "next non-overlapping difference");
}

}  // namespace allan
}  // namespace imu_lab
