#include "imu_lab/identify/fit_points.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace identify {

std::vector<FitPoint> select_fit_points(const std::vector<allan::StabilityPoint>& points, double min_ratio) {
  std::vector<FitPoint> kept;
  double previous_tau_s = 0.0;
  for (const auto& point : points) {
    if (!(point.tau_s > previous_tau_s)) {
      throw InputError("noise identification: stability points must have positive, increasing "
                       "tau (tau " + std::to_string(point.tau_s) + " s follows " +
                       std::to_string(previous_tau_s) + " s)");
    }
    previous_tau_s = point.tau_s;
    const bool usable = std::isfinite(point.deviation) && point.deviation > 0.0 && point.averaging_factor >= 1;
    if (!usable) continue;
    if (!kept.empty() && point.tau_s < min_ratio * kept.back().tau_s) continue;
    kept.push_back({point.tau_s, point.averaging_factor, point.deviation * point.deviation});
  }
  if (kept.size() < 3) {
    throw InputError("noise identification: need at least 3 usable stability points (positive deviation), got " +
                     std::to_string(kept.size()) + "; record a longer series or pass more averaging factors");
  }
  return kept;
}

std::vector<int> octave_averaging_factors(long long sample_count) {
  std::vector<int> factors;
  constexpr long long kLargestFactor = 1LL << 30;  // StabilityPoint holds m as an int
  for (long long m = 1; 2 * m <= sample_count - 1 && m <= kLargestFactor; m *= 2) {
    factors.push_back(static_cast<int>(m));
  }
  return factors;
}

}  // namespace identify
}  // namespace imu_lab
