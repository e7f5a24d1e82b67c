#include "imu_lab/calib/static_intervals.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/earth_constants.h"
#include "imu_lab/common/robust_statistics.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace calib {
StaticDetection detect_static_intervals(const std::vector<io::ImuRecord>& samples,
                                        const StaticDetectionOptions& options) {
  if (samples.size() < 2) throw InputError("calibration recording: fewer than 2 samples");
  for (std::size_t k = 1; k < samples.size(); ++k) {
    if (samples[k].stamp_ns <= samples[k - 1].stamp_ns) {
      throw InputError("calibration recording: stamps not increasing at sample " + std::to_string(k) + " (" +
                       format_stamp_s(samples[k].stamp_ns) + " s after " + format_stamp_s(samples[k - 1].stamp_ns) +
                       " s); record in order or sort the bag");
    }
  }
  const double sample_interval_s =
      seconds_between(samples.front().stamp_ns, samples.back().stamp_ns) / (samples.size() - 1);
  const std::size_t window = std::max<std::size_t>(1, std::lround(options.window_s / sample_interval_s));
  const std::size_t window_count = samples.size() / window;
  if (window_count < 3) throw InputError("calibration recording: too short to look for static intervals");

  std::vector<Eigen::Vector3d> window_means(window_count, Eigen::Vector3d::Zero());
  for (std::size_t w = 0; w < window_count; ++w) {
    for (std::size_t k = w * window; k < (w + 1) * window; ++k) window_means[w] += samples[k].angular_rate_rad_s;
    window_means[w] /= static_cast<double>(window);
  }
  // Noise from differences of neighbouring windows: robust to the minority of moving windows and
  // to the different Earth-rate projections of different rests.
  std::vector<double> differences;
  Eigen::Vector3d resting_level;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> level;
    for (std::size_t w = 0; w < window_count; ++w) {
      level.push_back(window_means[w][axis]);
      if (w > 0) differences.push_back(std::abs(window_means[w][axis] - window_means[w - 1][axis]));
    }
    resting_level[axis] = upper_median(level);
  }
  StaticDetection detection;
  detection.window_s = window * sample_interval_s;
  detection.window_noise_rad_s = sigma_from_absolute_differences(differences);
  detection.threshold_rad_s = options.threshold_rad_s > 0.0 ? options.threshold_rad_s
                                                            : options.threshold_sigmas * detection.window_noise_rad_s +
                                                                  2.0 * wgs84::kEarthRate_rad_s;

  detection.resting_level_rad_s = resting_level;
  if (resting_level.norm() > options.max_resting_rate_rad_s) return detection;

  const std::size_t min_windows = std::max<std::size_t>(3, std::ceil(options.min_duration_s / detection.window_s) + 2);
  std::size_t run_start = 0;
  for (std::size_t w = 0; w <= window_count; ++w) {
    const bool at_rest = w < window_count && (window_means[w] - resting_level).norm() < detection.threshold_rad_s;
    if (at_rest) continue;
    if (w - run_start >= min_windows) {
      // Trim one window at each end: it may hold the tail of a move.
      detection.intervals.push_back({(run_start + 1) * window, (w - 1) * window});
    }
    run_start = w + 1;
  }
  return detection;
}

}  // namespace calib
}  // namespace imu_lab
