// One level of the decimation pyramid for one channel: the phase of the rate averaged over 2^level
// samples, the current segment's ring and head, and the pooled sums of every statistic at the
// level's averaging factors.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "imu_lab/allan/checkpoint_codec.h"
#include "imu_lab/allan/streaming_block_autocorrelation.h"
#include "imu_lab/allan/streaming_compensated_sum.h"
#include "imu_lab/allan/streaming_difference_accumulator.h"
#include "imu_lab/allan/streaming_modified_accumulator.h"
#include "imu_lab/allan/streaming_phase_ring.h"

namespace imu_lab {
namespace allan {

class ResolutionLevel {
 public:
  // averaging_factors: m / 2^level, ascending. Opens an empty segment.
  ResolutionLevel(int level, std::vector<int> averaging_factors);

  // Phase points are in units of the input value times samples of this level
  // (x / tau0_level); the first point of each segment is 0 and is pushed here.
  // append_phase only stores the point; the statistics see it at the next process_appended()
  // (or when the ring must make room), which runs them over all stored points in one block.
  void append_phase(double phase);
  void process_appended();
  bool has_unprocessed_points() const { return processed_count_ != ring_.count(); }
  // Folds the segment's total-deviation end terms and length into the pooled sums, opens a new one.
  void restart_segment();

  int level() const { return level_; }
  std::int64_t phase_count() const { return ring_.count(); }  // of the open segment, its point 0 included
  double phase_scale() const { return phase_scale_; }         // 2^-level: level-0 phase to this level's units
  const std::vector<int>& averaging_factors() const { return averaging_factors_; }
  const DifferenceAccumulator& allan() const { return allan_; }
  const DifferenceAccumulator& hadamard() const { return hadamard_; }
  const ModifiedAccumulator& modified() const { return modified_; }
  const BlockMeanAutocorrelation& block_autocorrelation() const { return block_autocorrelation_; }
  // Pooled over closed segments and the open one (as if the run ended now).
  double total_end_terms_sum(std::size_t tau_index) const;
  // Phase point count -> number of segments with it; closed segments and the open one.
  std::map<std::int64_t, std::int64_t> segment_phase_counts() const;

  std::size_t heap_bytes() const;
  void save(BinaryWriter& out) const;
  void load(BinaryReader& in);

 private:
  bool open_segment_has_data() const { return ring_.count() >= 2; }

  int level_;
  double phase_scale_;
  std::vector<int> averaging_factors_;
  std::size_t head_capacity_;
  PhaseRing ring_;
  std::int64_t processed_count_ = 0;  // ring points the statistics have seen
  std::vector<double> head_;          // first points of the open segment
  DifferenceAccumulator allan_;
  DifferenceAccumulator hadamard_;
  ModifiedAccumulator modified_;
  BlockMeanAutocorrelation block_autocorrelation_;
  std::vector<CompensatedSum> closed_total_end_terms_;
  std::map<std::int64_t, std::int64_t> closed_segment_phase_counts_;
};

}  // namespace allan
}  // namespace imu_lab
