// Modified Allan variance and the time variance derived from it.
#include "imu_lab/allan/batch.h"

#include "batch_input_checks.h"

namespace imu_lab {
namespace allan {

// MVAR = < (sum_{i=j}^{j+m-1} (x[i+2m] - 2 x[i+m] + x[i]))^2 > / (2 m^2 tau^2), j = 0..N-3m.
// The inner sums slide along the series in O(1) each; they run over second differences
// (small, zero-mean numbers, unlike cumulative sums of x) in extended precision, so the
// O(N) pass per tau loses nothing to cancellation even over 10^7 samples.
double modified_allan_variance(const std::vector<double>& phase, double tau0_s, int m) {
  const long long terms = detail::require_computable(Statistic::kModifiedAllan, phase, tau0_s, m);
  const std::size_t lag = static_cast<std::size_t>(m);
  auto second_difference = [&](std::size_t i) { return phase[i + 2 * lag] - 2.0 * phase[i + lag] + phase[i]; };
  long double window = 0.0L;
  for (std::size_t i = 0; i < lag; ++i) window += second_difference(i);
  long double sum_of_squares = 0.0L;
  for (long long j = 0; j < terms; ++j) {
    sum_of_squares += window * window;
    if (j + 1 < terms) {
      const std::size_t start = static_cast<std::size_t>(j);
      window += second_difference(start + lag) - second_difference(start);
    }
  }
  const double tau_s = m * tau0_s;
  return static_cast<double>(sum_of_squares / terms) / (2.0 * static_cast<double>(m) * m * tau_s * tau_s);
}

// TVAR = tau^2 / 3 * MVAR (NIST SP 1065, 5.2.6).
double time_variance(const std::vector<double>& phase, double tau0_s, int m) {
  const double tau_s = m * tau0_s;
  return tau_s * tau_s / 3.0 * modified_allan_variance(phase, tau0_s, m);
}

}  // namespace allan
}  // namespace imu_lab
