#include "imu_lab/allan/streaming_options.h"

#include <cmath>
#include <string>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace allan {
namespace {

void require(bool condition, const char* key, const std::string& problem) {
  if (!condition) throw ConfigError("StreamingOptions", key, problem);
}

}  // namespace

void StreamingOptions::validate() const {
  require(channel_count >= 1, "channel_count", "must be at least 1");
  // A thousand per decade already resolves every m up to ~400 individually.
  require(std::isfinite(points_per_decade) && points_per_decade > 0.0 && points_per_decade <= kMaxPointsPerDecade,
          "points_per_decade", "must be a positive number up to 1000");
  require(std::isfinite(max_tau_s) && max_tau_s > 0.0, "max_tau_s", "must be a positive time in seconds");
  require(exact_max_averaging_factor >= 2 && exact_max_averaging_factor <= kMaxExactAveragingFactor,
          "exact_max_averaging_factor", "must be between 2 and 2^20 (about 0.5 GB of state per channel)");
  require(tau_spacing != TauSpacing::kEveryM || exact_max_averaging_factor <= kMaxEveryMExactFactor,
          "exact_max_averaging_factor", "must be at most 4096 with every-m spacing (one tau per m)");
  require(warm_up_sample_count >= 3, "warm_up_sample_count", "needs at least 3 samples to estimate tau0");
  require(std::isfinite(gap_factor) && gap_factor > 1.0, "gap_factor", "must be above 1 (1.5 is usual)");
  require(confidence > 0.0 && confidence < 1.0, "confidence", "must lie strictly between 0 and 1");
}

}  // namespace allan
}  // namespace imu_lab
