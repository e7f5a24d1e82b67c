#include "batch_input_checks.h"

#include <cmath>
#include <stdexcept>

namespace imu_lab {
namespace allan {
namespace detail {

void require_positive_tau0(double tau0_s, const std::string& caller) {
  if (!(tau0_s > 0.0) || !std::isfinite(tau0_s)) {
    throw std::invalid_argument(caller + ": tau0_s = " + std::to_string(tau0_s) +
                                " is not a positive sample interval; pass the sampling period"
                                " in seconds");
  }
}

void require_positive_averaging_factor(int m, const std::string& caller) {
  if (m < 1) {
    throw std::invalid_argument(caller + ": averaging factor m = " + std::to_string(m) +
                                " must be at least 1 (tau = m * tau0)");
  }
}

void require_finite_samples(const std::vector<double>& samples, const std::string& caller) {
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (!std::isfinite(samples[k])) {
      throw std::invalid_argument(caller + ": sample " + std::to_string(k) +
                                  " is not finite (NaN or infinity); remove or fill gaps"
                                  " before computing stability statistics");
    }
  }
}

long long require_computable(Statistic statistic, const std::vector<double>& phase, double tau0_s, int m) {
  const std::string caller = statistic_name(statistic) + " variance";
  require_positive_tau0(tau0_s, caller);
  require_positive_averaging_factor(m, caller);
  const long long terms = term_count(statistic, phase.size(), m);
  if (terms <= 0) {
    throw std::invalid_argument(caller + ": " + std::to_string(phase.size()) +
                                " phase samples are too few for averaging factor m = " + std::to_string(m) +
                                "; use a smaller m or a longer record");
  }
  require_finite_samples(phase, caller);
  return terms;
}

}  // namespace detail
}  // namespace allan
}  // namespace imu_lab
