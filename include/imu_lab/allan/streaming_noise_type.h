// Stable32's per-point noise-type rule (the batch estimate_noise_alpha) evaluated from the
// streaming summaries instead of the stored series: lag-1 autocorrelation of the block means when
// there are at least kMinimumLag1Points of them, else the B1 ratio, with MVAR/AVAR to split WPM
// from FPM. Identical to the batch rule for frequency-type data on one segment.
#pragma once

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/streaming_block_autocorrelation.h"

namespace imu_lab {
namespace allan {

// m: the averaging factor at the summary's resolution. modified_to_allan_ratio: MVAR / OAVAR at m,
// or a negative number when MVAR has no terms.
int streaming_noise_alpha(Statistic statistic, const BlockSeriesSummary& block_means, int m,
                          double modified_to_allan_ratio);

}  // namespace allan
}  // namespace imu_lab
