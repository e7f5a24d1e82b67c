// Frequency-type samples (rates) to phase-type samples (integrated rate).
#include "imu_lab/allan/batch.h"

#include "batch_input_checks.h"

namespace imu_lab {
namespace allan {

std::vector<double> phase_from_frequency(const std::vector<double>& frequency, double tau0_s) {
  detail::require_positive_tau0(tau0_s, "phase_from_frequency");
  detail::require_finite_samples(frequency, "phase_from_frequency");
  std::vector<double> phase(frequency.size() + 1);
  // Extended precision keeps each x[k] correctly rounded however long the record is.
  long double integral = 0.0L;
  phase[0] = 0.0;
  for (std::size_t k = 0; k < frequency.size(); ++k) {
    integral += static_cast<long double>(frequency[k]) * tau0_s;
    phase[k + 1] = static_cast<double>(integral);
  }
  return phase;
}

}  // namespace allan
}  // namespace imu_lab
