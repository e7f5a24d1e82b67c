// Stable32-style evaluation: deviation, '#', noise type, EDF and chi-squared bounds per tau.
#include <cmath>
#include <stdexcept>
#include <string>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/confidence.h"
#include "imu_lab/allan/edf.h"
#include "imu_lab/allan/noise_type.h"

#include "batch_input_checks.h"

namespace imu_lab {
namespace allan {
namespace {

std::vector<StabilityPoint> evaluate_points(Statistic statistic, const std::vector<double>& phase, double tau0_s,
                                            const std::vector<int>& averaging_factors, double confidence,
                                            SampleKind kind) {
  const std::string caller = "evaluate(" + statistic_name(statistic) + ")";
  detail::require_positive_tau0(tau0_s, caller);
  detail::require_finite_samples(phase, caller);
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw std::invalid_argument(caller + ": confidence = " + std::to_string(confidence) +
                                " must lie strictly between 0 and 1 (e.g. 0.683)");
  }
  std::vector<StabilityPoint> points;
  for (int m : averaging_factors) {
    detail::require_positive_averaging_factor(m, caller);
    StabilityPoint point;
    point.term_count = term_count(statistic, phase.size(), m);
    if (point.term_count <= 0) continue;  // too short a record for this tau
    point.averaging_factor = m;
    point.tau_s = m * tau0_s;
    point.deviation = std::sqrt(variance(statistic, phase, tau0_s, m));
    point.alpha = estimate_noise_alpha(statistic, phase, tau0_s, m, kind);
    point.edf = equivalent_degrees_of_freedom(statistic, point.alpha, m, static_cast<long long>(phase.size()));
    if (point.edf > 0.0) {
      const DeviationBounds bounds = chi_squared_bounds(point.deviation, point.edf, confidence);
      point.deviation_lower = bounds.lower;
      point.deviation_upper = bounds.upper;
    }
    points.push_back(point);
  }
  return points;
}

}  // namespace

double variance(Statistic statistic, const std::vector<double>& phase, double tau0_s, int m) {
  switch (statistic) {
    case Statistic::kAllan: return allan_variance(phase, tau0_s, m);
    case Statistic::kOverlappingAllan: return overlapping_allan_variance(phase, tau0_s, m);
    case Statistic::kModifiedAllan: return modified_allan_variance(phase, tau0_s, m);
    case Statistic::kHadamard: return hadamard_variance(phase, tau0_s, m);
    case Statistic::kOverlappingHadamard: return overlapping_hadamard_variance(phase, tau0_s, m);
    case Statistic::kTime: return time_variance(phase, tau0_s, m);
    case Statistic::kTotal: return total_variance(phase, tau0_s, m);
    case Statistic::kAllanKrobka: return allan_krobka_variance(phase, tau0_s, m);
    case Statistic::kHadamardKrobka: return hadamard_krobka_variance(phase, tau0_s, m);
  }
  throw std::invalid_argument("variance: unknown statistic " + std::to_string(static_cast<int>(statistic)));
}

std::vector<StabilityPoint> evaluate(Statistic statistic, const std::vector<double>& phase, double tau0_s,
                                     const std::vector<int>& averaging_factors, double confidence) {
  return evaluate_points(statistic, phase, tau0_s, averaging_factors, confidence, SampleKind::kPhase);
}

std::vector<StabilityPoint> evaluate_frequency(Statistic statistic, const std::vector<double>& frequency, double tau0_s,
                                               const std::vector<int>& averaging_factors, double confidence) {
  detail::require_finite_samples(frequency, "evaluate_frequency(" + statistic_name(statistic) + ")");
  // Every statistic here is blind to a frequency offset; removing the mean keeps the
  // integrated phase small, so its differences keep full double precision.
  long double sum = 0.0L;
  for (double value : frequency) sum += value;
  const double mean = frequency.empty() ? 0.0 : static_cast<double>(sum / frequency.size());
  std::vector<double> centred(frequency.size());
  for (std::size_t k = 0; k < frequency.size(); ++k) centred[k] = frequency[k] - mean;
  return evaluate_points(statistic, phase_from_frequency(centred, tau0_s), tau0_s, averaging_factors, confidence,
                         SampleKind::kFrequency);
}

}  // namespace allan
}  // namespace imu_lab
