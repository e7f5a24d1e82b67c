#include "imu_lab/allan/streaming_tau_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>

namespace imu_lab {
namespace allan {
namespace {

// The lowest pyramid level L where m / 2^L fits under the exact limit.
int level_holding(std::int64_t m, std::int64_t exact_limit) {
  int level = 0;
  while (m > (exact_limit << level)) ++level;
  return level;
}

std::vector<std::int64_t> requested_factors(const StreamingOptions& options, std::int64_t max_factor) {
  std::vector<std::int64_t> factors;
  if (options.tau_spacing == TauSpacing::kEveryM) {
    // Every m up to max_tau / tau0 could be 1e9 of them, but beyond the exact limit the plan
    // keeps only one per multiple of 2^L on level L: step from one such multiple to the next.
    for (std::int64_t m = 1; m <= max_factor;) {
      factors.push_back(m);
      const std::int64_t block = std::int64_t{1} << level_holding(m, options.exact_max_averaging_factor);
      m = (m + block - 1) / block * block + 1;
    }
    return factors;
  }
  return logarithmic_averaging_factors(options.points_per_decade, max_factor);
}

}  // namespace

std::vector<std::int64_t> logarithmic_averaging_factors(double points_per_decade, std::int64_t max_averaging_factor) {
  std::vector<std::int64_t> factors;
  for (int i = 0;; ++i) {
    const double m = std::round(std::pow(10.0, i / points_per_decade));
    if (m > static_cast<double>(max_averaging_factor)) break;
    if (factors.empty() || factors.back() != static_cast<std::int64_t>(m)) {
      factors.push_back(static_cast<std::int64_t>(m));
    }
  }
  return factors;
}

TauPlan plan_taus(const StreamingOptions& options, double tau0_s) {
  // StabilityPoint holds m as an int; far beyond any run length anyway.
  const double max_factor_real =
      std::min(std::floor(options.max_tau_s / tau0_s), static_cast<double>(std::numeric_limits<int>::max() / 2));
  const std::int64_t max_factor = std::max<std::int64_t>(1, static_cast<std::int64_t>(max_factor_real));
  const std::int64_t exact_limit = options.exact_max_averaging_factor;

  std::map<int, std::set<int>> factors_by_level;
  for (const std::int64_t m : requested_factors(options, max_factor)) {
    const int level = level_holding(m, exact_limit);
    // Rounding up keeps every level's reported factors above the previous level's.
    const std::int64_t block = std::int64_t{1} << level;
    factors_by_level[level].insert(static_cast<int>((m + block - 1) / block));
  }

  TauPlan plan;
  for (const auto& entry : factors_by_level) {
    PlannedLevel planned;
    planned.level = entry.first;
    planned.level_averaging_factors.assign(entry.second.begin(), entry.second.end());
    plan.levels.push_back(planned);
  }
  return plan;
}

}  // namespace allan
}  // namespace imu_lab
