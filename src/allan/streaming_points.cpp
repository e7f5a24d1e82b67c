#include "imu_lab/allan/streaming_points.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "imu_lab/allan/confidence.h"
#include "imu_lab/allan/edf.h"
#include "imu_lab/allan/streaming_noise_type.h"

namespace imu_lab {
namespace allan {
namespace {

struct VarianceEstimate {
  double variance = 0.0;  // in accumulated units squared; TVAR in accumulated units times seconds, squared
  long long term_count = 0;
};

double squared(double value) { return value * value; }

// Sum of squared binomial coefficients of the (order-1)-th difference of the mean rate: 2 for
// Allan, 6 for Hadamard.
double difference_normaliser(int order) { return order == 2 ? 2.0 : 6.0; }

VarianceEstimate mean_square_estimate(const DifferenceSums& sums, int order, int m) {
  return {sums.mean_square() / (difference_normaliser(order) * squared(m)), sums.count};
}

// Krobka 2015 (eq. 5.10): the mean square minus the squared mean, the mean taken per segment.
VarianceEstimate dispersion_estimate(const DifferenceAccumulator& differences, std::size_t i, int m) {
  const DifferenceSums sums = differences.overlapping(i);
  if (sums.count == 0) return {};
  const double spread = std::max(0.0, differences.overlapping_spread(i)) / sums.count;
  return {spread / (difference_normaliser(differences.order()) * squared(m)), sums.count};
}

long long total_normaliser(const ResolutionLevel& level, int m) {
  long long normaliser = 0;
  for (const auto& entry : level.segment_phase_counts()) {
    if (entry.first >= 2LL * m + 1) normaliser += (entry.first - 2) * entry.second;
  }
  return normaliser;
}

VarianceEstimate estimate(Statistic statistic, const ResolutionLevel& level, std::size_t i, double tau_s) {
  const int m = level.averaging_factors()[i];
  switch (statistic) {
    case Statistic::kAllan: return mean_square_estimate(level.allan().non_overlapping(i), 2, m);
    case Statistic::kOverlappingAllan: return mean_square_estimate(level.allan().overlapping(i), 2, m);
    case Statistic::kAllanKrobka: return dispersion_estimate(level.allan(), i, m);
    case Statistic::kHadamard: return mean_square_estimate(level.hadamard().non_overlapping(i), 3, m);
    case Statistic::kOverlappingHadamard: return mean_square_estimate(level.hadamard().overlapping(i), 3, m);
    case Statistic::kHadamardKrobka: return dispersion_estimate(level.hadamard(), i, m);
    case Statistic::kModifiedAllan:
    case Statistic::kTime: {
      // Each term sums m second differences: MVAR = <W^2> / (2 m^4) in rate units
      // (NIST SP 1065 eq. 14 with x = tau0 * accumulated phase).
      const DifferenceSums& terms = level.modified().terms(i);
      const double modified = terms.mean_square() / (2.0 * std::pow(static_cast<double>(m), 4));
      const double scale = statistic == Statistic::kTime ? tau_s * tau_s / 3.0 : 1.0;
      return {modified * scale, terms.count};
    }
    case Statistic::kTotal: {
      // The N-2m interior terms are the overlapping Allan terms; the ends come from head and tail.
      const long long normaliser = total_normaliser(level, m);
      if (normaliser == 0) return {};
      const double squares = level.allan().overlapping(i).squares.value() + level.total_end_terms_sum(i);
      return {squares / (2.0 * squared(m) * normaliser), normaliser};
    }
  }
  throw std::invalid_argument("streaming_points: unknown statistic");
}

struct SegmentPooling {
  double edf = 0.0;            // independent segments add their degrees of freedom
  double term_fraction = 1.0;  // the terms against those of one record holding every segment's phase points
};

// One pass over the level's segments for both.
SegmentPooling pool_segments(Statistic statistic, const ResolutionLevel& level, int m, int alpha, long long terms) {
  SegmentPooling pooled;
  std::size_t phase_points = 0;
  for (const auto& entry : level.segment_phase_counts()) {
    phase_points += static_cast<std::size_t>(entry.first * entry.second);
    if (term_count(statistic, static_cast<std::size_t>(entry.first), m) <= 0) continue;
    try {
      pooled.edf += entry.second * equivalent_degrees_of_freedom(statistic, alpha, m, entry.first);
    } catch (const std::invalid_argument&) {
      // Too short a segment for an EDF: it adds its terms but no confidence.
    }
  }
  const long long contiguous = term_count(statistic, phase_points, m);
  if (contiguous > 0)
    pooled.term_fraction = std::min(1.0, static_cast<double>(terms) / static_cast<double>(contiguous));
  return pooled;
}

}  // namespace

std::vector<StabilityPoint> streaming_points(Statistic statistic, const ChannelAccumulator& channel,
                                             const PointUnits& units) {
  std::vector<StabilityPoint> points;
  for (const ResolutionLevel& level : channel.levels()) {
    const int block = 1 << level.level();
    LevelHistoryPhase history_phase(channel.history(), level.level());
    for (std::size_t i = 0; i < level.averaging_factors().size(); ++i) {
      const int level_m = level.averaging_factors()[i];
      StabilityPoint point;
      point.averaging_factor = level_m * block;
      point.tau_s = point.averaging_factor * units.tau0_s;
      const VarianceEstimate variance = estimate(statistic, level, i, point.tau_s);
      if (variance.term_count <= 0) continue;
      point.term_count = variance.term_count;
      point.deviation = std::sqrt(variance.variance) * units.value_scale;
      // Sums that overflowed (samples beyond ~1e150) estimate nothing.
      if (!std::isfinite(point.deviation)) continue;
      point.alpha = streaming_noise_alpha(statistic, level.block_autocorrelation().summary(i), history_phase, level_m,
                                          units.tau0_s);
      const SegmentPooling pooled = pool_segments(statistic, level, level_m, point.alpha, variance.term_count);
      point.pooled_term_fraction = pooled.term_fraction;
      point.edf = pooled.edf;
      if (point.edf > 0.0 && std::isfinite(point.edf)) {
        const DeviationBounds bounds = chi_squared_bounds(point.deviation, point.edf, units.confidence);
        point.deviation_lower = bounds.lower;
        point.deviation_upper = bounds.upper;
      }
      points.push_back(point);
    }
  }
  return points;
}

}  // namespace allan
}  // namespace imu_lab
