#include "imu_lab/identify/white_equivalent.h"

#include <cmath>
#include <limits>

namespace imu_lab {
namespace identify {

bool markov_acts_as_low_passed_white(double correlation_time_s, double shortest_tau_s) {
  return correlation_time_s < 2.0 * shortest_tau_s;
}

double white_equivalent_density(const FitResult& fit) {
  bool filter_modelled = false;
  for (const Term& term : fit.model.terms) filter_modelled |= term.kind == TermKind::kWhiteRate && term.shape > 0.0;
  double power = 0.0;
  bool any = false;
  for (const TermEstimate& term : fit.terms) {
    if (term.status != TermStatus::kPresent || !std::isfinite(term.amplitude.value)) continue;
    const bool white = term.kind == TermKind::kWhiteRate;
    const bool low_passed_white = term.kind == TermKind::kMarkov && !filter_modelled && !fit.points.empty() &&
                                  markov_acts_as_low_passed_white(term.shape.value, fit.points.front().tau_s);
    if (!white && !low_passed_white) continue;
    power += term.amplitude.value * term.amplitude.value;
    any = true;
  }
  return any ? std::sqrt(power) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace identify
}  // namespace imu_lab
