// Howe's total variance (TOTVAR).
#include "imu_lab/allan/batch.h"

#include "batch_input_checks.h"

namespace imu_lab {
namespace allan {

// TOTVAR = sum_{k=1}^{N-2} (x*[k-m] - 2 x[k] + x*[k+m])^2 / (2 tau^2 (N-2)), where x* extends
// the phase by odd reflection about each end point: x*[-j] = 2 x[0] - x[j] and
// x*[N-1+j] = 2 x[N-1] - x[N-1-j] (NIST SP 1065, 5.2.11). Reflection keeps a linear phase
// (frequency offset) linear, so the statistic stays blind to it.
double total_variance(const std::vector<double>& phase, double tau0_s, int m) {
  const long long terms = detail::require_computable(Statistic::kTotal, phase, tau0_s, m);
  const long long last = static_cast<long long>(phase.size()) - 1;
  auto extended = [&](long long i) {
    if (i < 0) return 2.0 * phase[0] - phase[-i];
    if (i > last) return 2.0 * phase[last] - phase[2 * last - i];
    return phase[i];
  };
  long double sum_of_squares = 0.0L;
  for (long long k = 1; k < last; ++k) {
    const double difference = extended(k - m) - 2.0 * phase[k] + extended(k + m);
    sum_of_squares += static_cast<long double>(difference) * difference;
  }
  const double tau_s = m * tau0_s;
  return static_cast<double>(sum_of_squares / terms) / (2.0 * tau_s * tau_s);
}

}  // namespace allan
}  // namespace imu_lab
