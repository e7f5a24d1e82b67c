// Batch reference for the streaming engine beyond its exact limit: average the rate over
// complete blocks of 2^level samples (doc/models.md: averaging y, not x), then run the batch
// statistic on the averaged series at m / 2^level with tau0 * 2^level. The term count and EDF
// are those of this decimated estimator.
#pragma once

#include <vector>

#include "imu_lab/allan/batch.h"

namespace imu_lab {
namespace allan {

// Means over blocks [k 2^level, (k+1) 2^level); an incomplete last block is dropped.
std::vector<double> average_rate_blocks(const std::vector<double>& frequency, int level);

// Points at m = level_factor * 2^level (averaging_factor and tau_s in input samples and seconds).
std::vector<StabilityPoint> evaluate_decimated_frequency(Statistic statistic, const std::vector<double>& frequency,
                                                         double tau0_s, int level,
                                                         const std::vector<int>& level_averaging_factors,
                                                         double confidence = 0.683);

}  // namespace allan
}  // namespace imu_lab
