// Stable32's per-point noise-type rule as the batch estimate_noise_alpha applies it to
// frequency-type data: the lag-1 autocorrelation of the block means, here from running sums,
// where there are at least kMinimumLag1Points of them; else the batch rule itself on the short
// phase the history holds. Identical to the batch rule on one segment.
#pragma once

#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/streaming_block_autocorrelation.h"
#include "imu_lab/allan/streaming_phase_history.h"

namespace imu_lab {
namespace allan {

// The history's phase at one pyramid level (PhaseHistory::phase_at_level), built on first use:
// every short-record tau of the level shares it, and building it copies up to 30 m_exact + 1
// points, the largest part of a snapshot when built again for each tau.
class LevelHistoryPhase {
 public:
  LevelHistoryPhase(const PhaseHistory& history, int level) : history_(&history), level_(level) {}
  int level() const { return level_; }
  const std::vector<double>& phase();

 private:
  const PhaseHistory* history_;
  int level_;
  bool built_ = false;
  std::vector<double> phase_;
};

// m: the averaging factor at the level's resolution; tau0_s: the input's.
int streaming_noise_alpha(Statistic statistic, const BlockSeriesSummary& block_means, LevelHistoryPhase& history_phase,
                          int m, double tau0_s);

}  // namespace allan
}  // namespace imu_lab
