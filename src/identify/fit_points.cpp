#include "imu_lab/identify/fit_points.h"

#include <algorithm>
#include <cmath>
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
std::vector<int> ladder_factors(double largest) {
  std::vector<int> factors;
  for (int k = 0;; ++k) {
    const long long m = std::llround(std::pow(10.0, k / kLadderPointsPerDecade));
    if (m > largest) break;
    if (factors.empty() || m != factors.back()) factors.push_back(static_cast<int>(m));
  }
  return factors;
}

// |ln(a / b)|: how far apart two averaging factors lie on a log tau axis.
double log_distance(int a, int b) { return std::abs(std::log(static_cast<double>(a) / b)); }

// The usable points nearest the ladder's factors, when the curve's grid holds (nearly) all of it.
// Each factor takes the curve point nearest it in log tau, if within kLadderTolerance: the
// engine's reported factor beyond its exact range is the target rounded to a pyramid block, and
// every decade grid rounds it to the same block, so any density yields the same points.
std::vector<FitPoint> ladder_points(const std::vector<allan::StabilityPoint>& points) {
  int largest = 0;
  for (const auto& point : points) {
    if (usable(point)) largest = std::max(largest, point.averaging_factor);
  }
  const std::vector<int> ladder = ladder_factors(largest * (1.0 + kLadderTolerance));
  const double tolerance = std::log1p(kLadderTolerance);
  std::size_t present = 0;
  std::vector<FitPoint> kept;
  for (int target : ladder) {
    const allan::StabilityPoint* nearest = nullptr;
    for (const auto& point : points) {
      if (point.averaging_factor < 1) continue;  // no place on a log axis
      if (nearest == nullptr ||
          log_distance(point.averaging_factor, target) < log_distance(nearest->averaging_factor, target)) {
        nearest = &point;
      }
    }
    if (nearest == nullptr || log_distance(nearest->averaging_factor, target) > tolerance) continue;
    ++present;
    if (usable(*nearest)) kept.push_back(fit_point(*nearest));
  }
  if (ladder.empty() || present < 0.8 * static_cast<double>(ladder.size())) return {};
  return kept;
}

}  // namespace

std::vector<FitPoint> select_fit_points(const std::vector<allan::StabilityPoint>& points, double min_ratio) {
  std::vector<FitPoint> kept;
  double previous_tau_s = 0.0;
  for (const auto& point : points) {
    if (!(point.tau_s > previous_tau_s)) {
      throw InputError(
          "noise identification: stability points must have positive, increasing "
          "tau (tau " +
          std::to_string(point.tau_s) + " s follows " + std::to_string(previous_tau_s) + " s)");
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
