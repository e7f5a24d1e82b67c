#include "imu_lab/identify/fit_points.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace identify {

namespace {

FitPoint fit_point(const allan::StabilityPoint& point) {
  return {point.tau_s, point.averaging_factor, point.deviation * point.deviation, point.pooled_term_fraction};
}

bool usable(const allan::StabilityPoint& point) {
  return std::isfinite(point.deviation) && point.deviation > 0.0 && point.averaging_factor >= 1;
}

// The ladder's factors round(10^(k / 5)) up to `largest`.
std::vector<int> ladder_factors(int largest) {
  std::vector<int> factors;
  for (int k = 0;; ++k) {
    const long long m = std::llround(std::pow(10.0, k / kLadderPointsPerDecade));
    if (m > largest) break;
    if (factors.empty() || m != factors.back()) factors.push_back(static_cast<int>(m));
  }
  return factors;
}

// The usable points on the ladder, when the curve's grid holds (nearly) all of it.
std::vector<FitPoint> ladder_points(const std::vector<allan::StabilityPoint>& points) {
  std::set<int> on_curve;
  int largest = 0;
  for (const auto& point : points) {
    on_curve.insert(point.averaging_factor);
    if (usable(point)) largest = std::max(largest, point.averaging_factor);
  }
  const std::vector<int> ladder = ladder_factors(largest);
  std::size_t present = 0;
  for (int m : ladder) present += on_curve.count(m);
  if (ladder.empty() || present < 0.8 * static_cast<double>(ladder.size())) return {};
  std::vector<FitPoint> kept;
  for (const auto& point : points) {
    const bool first_at_factor = kept.empty() || kept.back().averaging_factor != point.averaging_factor;
    if (usable(point) && first_at_factor && std::binary_search(ladder.begin(), ladder.end(), point.averaging_factor)) {
      kept.push_back(fit_point(point));
    }
  }
  return kept;
}

}  // namespace

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
    if (!usable(point)) continue;
    if (!kept.empty() && point.tau_s < min_ratio * kept.back().tau_s) continue;
    kept.push_back(fit_point(point));
  }
  std::vector<FitPoint> ladder = ladder_points(points);
  if (ladder.size() >= 3) kept = std::move(ladder);
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
