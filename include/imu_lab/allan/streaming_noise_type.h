// Stable32's per-point noise-type rule as the batch estimate_noise_alpha applies it to
// frequency-type data: the lag-1 autocorrelation of the block means, here from running sums,
// where there are at least kMinimumLag1Points of them; else the batch rule itself on the short
// phase the history holds. Identical to the batch rule on one segment.
#pragma once

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/streaming_block_autocorrelation.h"
#include "imu_lab/allan/streaming_phase_history.h"

namespace imu_lab {
namespace allan {

// level, m: the pyramid level and the averaging factor at its resolution; tau0_s: the input's.
int streaming_noise_alpha(Statistic statistic, const BlockSeriesSummary& block_means,
                          const PhaseHistory& history, int level, int m, double tau0_s);

}  // namespace allan
}  // namespace imu_lab
