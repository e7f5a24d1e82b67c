// Which averaging factors the streaming engine evaluates, and at which pyramid level.
// Level 0 is the input rate; level L holds the rate averaged over 2^L samples. A factor up to the
// exact limit lives on level 0; a larger one on the lowest level L where m / 2^L fits under the
// limit, rounded to a multiple of 2^L (the reported m is that multiple).
#pragma once

#include <cstdint>
#include <vector>

#include "imu_lab/allan/streaming_options.h"

namespace imu_lab {
namespace allan {

struct PlannedLevel {
  int level = 0;                             // rate averaged over 2^level samples
  std::vector<int> level_averaging_factors;  // m / 2^level, ascending
};

struct TauPlan {
  std::vector<PlannedLevel> levels;  // ascending level; only levels with factors
};

// The logarithmic grid's averaging factors up to max_averaging_factor: round(10^(i /
// points_per_decade)), duplicates removed (the allan tool's default grid at 10 per decade).
std::vector<std::int64_t> logarithmic_averaging_factors(double points_per_decade, std::int64_t max_averaging_factor);

// max_averaging_factor = floor(max_tau_s / tau0); at least 1.
TauPlan plan_taus(const StreamingOptions& options, double tau0_s);

}  // namespace allan
}  // namespace imu_lab
