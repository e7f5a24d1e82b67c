#include "imu_lab/rate_table/plateaus.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/robust_statistics.h"

namespace imu_lab {
namespace rate_table {
namespace {

// A threshold below this would split plateaus of noise-free data on rounding alone.
constexpr double kThresholdFloor_rad_s = 1e-9;

}  // namespace

PlateauDetection detect_plateaus(const std::vector<double>& stamps_s, const std::vector<double>& rate_rad_s,
                                 const PlateauOptions& options) {
  if (stamps_s.size() != rate_rad_s.size())
    throw std::invalid_argument("detect_plateaus: stamps and rates differ in length");
  for (std::size_t k = 1; k < stamps_s.size(); ++k) {
    if (!(stamps_s[k] > stamps_s[k - 1])) {
      std::ostringstream message;
      message << "rate-table recording: stamps not increasing at sample " << k << " (" << stamps_s[k] << " s after "
              << stamps_s[k - 1] << " s); record in order or sort the bag";
      throw InputError(message.str());
    }
  }
  const double sample_interval_s =
      stamps_s.size() < 2 ? 0.0 : (stamps_s.back() - stamps_s.front()) / (stamps_s.size() - 1);
  const std::size_t window =
      sample_interval_s > 0.0 ? std::max<std::size_t>(1, std::lround(options.window_s / sample_interval_s)) : 1;
  const std::size_t window_count = rate_rad_s.size() / window;
  if (window_count < 3) {
    throw InputError("rate-table recording: " + std::to_string(rate_rad_s.size()) +
                     " samples, fewer than three plateau-detection windows");
  }
  std::vector<double> means(window_count, 0.0);
  for (std::size_t w = 0; w < window_count; ++w) {
    for (std::size_t k = w * window; k < (w + 1) * window; ++k) means[w] += rate_rad_s[k];
    means[w] /= static_cast<double>(window);
  }
  std::vector<double> differences;
  for (std::size_t w = 1; w < window_count; ++w) differences.push_back(std::abs(means[w] - means[w - 1]));

  PlateauDetection detection;
  detection.window_s = window * sample_interval_s;
  detection.window_noise_rad_s = sigma_from_absolute_differences(differences);
  detection.threshold_rad_s =
      options.threshold_rad_s > 0.0
          ? options.threshold_rad_s
          : std::max(options.threshold_sigmas * detection.window_noise_rad_s, kThresholdFloor_rad_s);
  const double threshold = detection.threshold_rad_s;

  const auto steady = [&](std::size_t w) {
    const bool left = w == 0 || std::abs(means[w] - means[w - 1]) <= threshold;
    const bool right = w + 1 == window_count || std::abs(means[w + 1] - means[w]) <= threshold;
    return left && right;
  };
  const std::size_t guard_windows = std::max<std::size_t>(1, std::ceil(options.guard_s / detection.window_s - 1e-9));
  const auto keep_run = [&](std::size_t first, std::size_t last) {  // steady windows [first, last)
    // A slow ramp passes the neighbour test: trim the end farther from the run's median until the
    // spread is within twice the threshold.
    while (last - first > 1) {
      const auto [low, high] = std::minmax_element(means.begin() + first, means.begin() + last);
      if (*high - *low <= 2.0 * threshold) break;
      const double middle = upper_median(std::vector<double>(means.begin() + first, means.begin() + last));
      if (std::abs(means[first] - middle) >= std::abs(means[last - 1] - middle)) {
        ++first;
      } else {
        --last;
      }
    }
    if (last - first <= 2 * guard_windows) return;
    Plateau plateau;
    plateau.begin = (first + guard_windows) * window;
    plateau.end = (last - guard_windows) * window;
    plateau.start_s = stamps_s[plateau.begin];
    plateau.duration_s = plateau.size() * sample_interval_s;
    if (plateau.duration_s < options.min_duration_s) return;
    double sum = 0.0;
    for (std::size_t k = plateau.begin; k < plateau.end; ++k) sum += rate_rad_s[k];
    plateau.level_rad_s = sum / static_cast<double>(plateau.size());
    detection.plateaus.push_back(plateau);
  };
  std::size_t run_start = 0;
  for (std::size_t w = 0; w <= window_count; ++w) {
    if (w < window_count && steady(w)) continue;
    if (w > run_start) keep_run(run_start, w);
    run_start = w + 1;
  }
  return detection;
}

}  // namespace rate_table
}  // namespace imu_lab
