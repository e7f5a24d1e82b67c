// Allan-type (order 2) or Hadamard-type (order 3) phase differences at a set of averaging
// factors, accumulated over a block of new phase points at a time (one tight loop per factor,
// plain partial sums folded once per block, streaming_block_sums.h): fully overlapping (every start index) and
// non-overlapping (start indices that are multiples of m). Sums persist across segments, which
// pools them; only the per-segment position is reset. For Krobka's dispersion the spread about
// the mean difference is taken within each segment (a gap may hide a bias jump) and pooled.
#pragma once

#include <cstdint>
#include <vector>

#include "imu_lab/allan/streaming_difference_sums.h"
#include "imu_lab/allan/streaming_phase_ring.h"

namespace imu_lab {
namespace allan {

class DifferenceAccumulator {
 public:
  // averaging_factors ascending; the ring must hold order * max(m) + 1 points.
  DifferenceAccumulator(int order, std::vector<int> averaging_factors);

  void start_segment();  // folds the open segment's spread into the pooled one
  // Every phase point from first_index to ring.newest() (those the ring received since the last
  // update); the ring must still hold order * max(m) points before first_index.
  void update(const PhaseRing& ring, std::int64_t first_index);

  int order() const { return order_; }
  DifferenceSums overlapping(std::size_t tau_index) const;  // pooled: closed segments and the open one
  const DifferenceSums& non_overlapping(std::size_t tau_index) const { return non_overlapping_[tau_index]; }
  // Sum over segments of sum_k (d_k - segment mean)^2 of the overlapping differences.
  double overlapping_spread(std::size_t tau_index) const;
  std::size_t heap_bytes() const;

  void save(BinaryWriter& out) const;
  // processed_count: the level's points already folded in (checks where the next ones resume).
  void load(BinaryReader& in, std::int64_t processed_count);

 private:
  int order_;
  std::vector<int> averaging_factors_;
  std::vector<DifferenceSums> open_segment_overlapping_;
  std::vector<DifferenceSums> closed_overlapping_;
  std::vector<DifferenceSums> non_overlapping_;
  std::vector<CompensatedSum> closed_spread_;
  std::vector<std::int64_t> next_non_overlapping_end_;  // phase index ending the next such term
};

}  // namespace allan
}  // namespace imu_lab
