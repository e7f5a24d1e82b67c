#include "imu_lab/allan/streaming_noise_type.h"

#include <algorithm>
#include <cmath>

#include "imu_lab/allan/noise_type.h"

namespace imu_lab {
namespace allan {
namespace {

bool is_hadamard_family(Statistic statistic) {
  return statistic == Statistic::kHadamard || statistic == Statistic::kOverlappingHadamard ||
         statistic == Statistic::kHadamardKrobka;
}

// lag1_autocorrelation_alpha's loop on summaries: difference until delta = r1 / (1 + r1) < 0.25,
// then alpha = -round(2 delta) - 2d (frequency data).
int lag1_alpha(const BlockSeriesSummary& block_means, int max_differences) {
  for (int d = 0;; ++d) {
    const double denominator = block_means.centred_squares[d];
    const double r1 = denominator > 0.0 ? block_means.lag1_numerator[d] / denominator : 0.0;
    const double delta = r1 / (1.0 + r1);
    if (delta < 0.25 || d >= max_differences || block_means.count[d] < 3) {
      return -static_cast<int>(std::lround(2.0 * delta)) - 2 * d;
    }
  }
}

}  // namespace

const std::vector<double>& LevelHistoryPhase::phase() {
  if (!built_) {
    phase_ = history_->phase_at_level(level_);
    built_ = true;
  }
  return phase_;
}

int streaming_noise_alpha(Statistic statistic, const BlockSeriesSummary& block_means, LevelHistoryPhase& history_phase,
                          int m, double tau0_s) {
  const bool hadamard = is_hadamard_family(statistic);
  if (block_means.count[0] >= kMinimumLag1Points) {
    return std::clamp(lag1_alpha(block_means, hadamard ? 3 : 2), hadamard ? -4 : -2, 2);
  }
  const std::vector<double>& phase = history_phase.phase();
  if (phase.size() < 2) return 0;  // white FM, the batch rule's neutral answer
  return estimate_noise_alpha(statistic, phase, std::ldexp(tau0_s, history_phase.level()), m, SampleKind::kFrequency);
}

}  // namespace allan
}  // namespace imu_lab
