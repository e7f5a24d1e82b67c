// One input channel: removes its offset, integrates the rate into phase (compensated, so 1e8
// samples keep full precision), and feeds every pyramid level its sub-sampled phase. The levels
// run their statistics when their ring fills (or at flush()), so a block of samples costs one
// tight loop per averaging factor instead of one pass over them per sample.
#pragma once

#include <cstdint>
#include <vector>

#include "imu_lab/allan/checkpoint_codec.h"
#include "imu_lab/allan/streaming_compensated_sum.h"
#include "imu_lab/allan/streaming_level.h"
#include "imu_lab/allan/streaming_phase_history.h"
#include "imu_lab/allan/streaming_tau_plan.h"

namespace imu_lab {
namespace allan {

class ChannelAccumulator {
 public:
  // history_capacity: see PhaseHistory (kMinimumLag1Points * m_exact + 1).
  ChannelAccumulator(const TauPlan& plan, double offset, std::size_t history_capacity);

  void push(double value);  // a finite value; the caller screens NaN/Inf
  void flush();             // brings every statistic up to the last pushed value
  bool has_unprocessed_points() const;
  void break_segment();  // a gap: the next value starts a new segment (flushes)

  double offset() const { return offset_; }
  const std::vector<ResolutionLevel>& levels() const { return levels_; }
  const PhaseHistory& history() const { return history_; }

  std::size_t heap_bytes() const;
  void save(BinaryWriter& out) const;
  void load(BinaryReader& in);

 private:
  double offset_;
  CompensatedSum phase_;
  std::int64_t segment_sample_count_ = 0;
  std::vector<ResolutionLevel> levels_;
  PhaseHistory history_;
};

}  // namespace allan
}  // namespace imu_lab
