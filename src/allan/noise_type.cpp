// Stable32's per-point noise-type estimate: lag-1 autocorrelation, B1 ratio and R(n).
#include "imu_lab/allan/noise_type.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace imu_lab {
namespace allan {
namespace {

// Lag-1 autocorrelation about the mean (Riley & Greenhall eq. 2); 0 for a constant series.
double lag1_autocorrelation(const std::vector<double>& z) {
  double mean = 0.0;
  for (double value : z) mean += value;
  mean /= static_cast<double>(z.size());
  double numerator = 0.0;
  double denominator = 0.0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    const double centred = z[i] - mean;
    denominator += centred * centred;
    if (i + 1 < z.size()) numerator += centred * (z[i + 1] - mean);
  }
  return denominator > 0.0 ? numerator / denominator : 0.0;
}

// The series at tau = m tau0: every m-th phase sample, or the block means of frequency.
std::vector<double> series_at_tau(const std::vector<double>& phase, double tau0_s, int m, SampleKind kind) {
  const std::size_t lag = static_cast<std::size_t>(m);
  std::vector<double> series;
  series.reserve(phase.size() / lag + 1);
  for (std::size_t k = 0; k < phase.size(); k += lag) series.push_back(phase[k]);
  if (kind == SampleKind::kFrequency) {
    for (std::size_t k = 0; k + 1 < series.size(); ++k) {
      series[k] = (series[k + 1] - series[k]) / (m * tau0_s);
    }
    series.pop_back();
  }
  return series;
}

// Phase-PSD exponent mu of AVAR ~ tau^mu for frequency exponent alpha (WPM and FPM share -2).
int mu_from_alpha(int alpha) { return alpha >= 1 ? -2 : -alpha - 1; }

// B1 with boundaries at the geometric means of neighbouring expectations; returns mu.
int b1_ratio_mu(double measured_ratio, long long b1_count, int lowest_alpha) {
  for (int mu = mu_from_alpha(lowest_alpha); mu > -2; --mu) {
    const double boundary = std::sqrt(expected_b1_ratio(b1_count, mu) * expected_b1_ratio(b1_count, mu - 1));
    if (measured_ratio > boundary) return mu;
  }
  return -2;
}

// The largest m' <= m that leaves at least kMinimumB1Points averages and estimator terms.
// Found by matching Stable32 1.60: with fewer, its estimate is that of a shorter tau
// (e.g. PHASE.DAT at m = 128 and the OCXO's longest taus), which a ratio of a handful of
// averages could not otherwise reproduce.
int b1_averaging_factor(Statistic statistic, std::size_t phase_count, int m) {
  const long long frequency_count = static_cast<long long>(phase_count) - 1;
  while (m > 1 &&
         (frequency_count / m < kMinimumB1Points || term_count(statistic, phase_count, m) < kMinimumB1Points)) {
    --m;
  }
  return m;
}

// B1 (expected value taken at the statistic's own term count, as Stable32 does), refined by
// R(n) = MVAR/AVAR where B1 only says "phase noise": R(n) falls as 1/m for WPM, slowly for
// FPM and tends to 1/2 for WFM, so it separates all three.
int b1_fallback_alpha(Statistic statistic, const std::vector<double>& phase, double tau0_s, int m, int lowest_alpha) {
  m = b1_averaging_factor(statistic, phase.size(), m);
  const std::vector<double> averages = series_at_tau(phase, tau0_s, m, SampleKind::kFrequency);
  const long long n = static_cast<long long>(averages.size());
  if (n < 2) return 0;  // nothing to compare; white FM is the neutral assumption
  double mean = 0.0;
  for (double value : averages) mean += value;
  mean /= static_cast<double>(n);
  double spread = 0.0;
  double successive = 0.0;
  for (long long i = 0; i < n; ++i) {
    spread += (averages[i] - mean) * (averages[i] - mean);
    if (i + 1 < n) successive += (averages[i + 1] - averages[i]) * (averages[i + 1] - averages[i]);
  }
  if (successive <= 0.0) return 0;
  const double sample_variance = spread / static_cast<double>(n - 1);
  const double two_sample_variance = successive / (2.0 * static_cast<double>(n - 1));
  const long long b1_count = std::max(2LL, term_count(statistic, phase.size(), m));
  const int mu = b1_ratio_mu(sample_variance / two_sample_variance, b1_count, lowest_alpha);
  if (mu > -2) return -mu - 1;
  if (term_count(Statistic::kModifiedAllan, phase.size(), m) <= 0) return 1;
  const double ratio = modified_allan_variance(phase, tau0_s, m) / overlapping_allan_variance(phase, tau0_s, m);
  const double white_fm_ratio = 0.5;
  if (ratio > std::sqrt(expected_modified_ratio(1, m) * white_fm_ratio)) return 0;
  return ratio > std::sqrt(expected_modified_ratio(1, m) * expected_modified_ratio(2, m)) ? 1 : 2;
}

}  // namespace

int lag1_autocorrelation_alpha(std::vector<double> series, int max_differences, SampleKind kind) {
  if (series.size() < 3) {
    throw std::invalid_argument("lag1_autocorrelation_alpha: " + std::to_string(series.size()) +
                                " points are too few; the method needs at least " + std::to_string(kMinimumLag1Points));
  }
  for (int d = 0;; ++d) {
    const double r1 = lag1_autocorrelation(series);
    const double delta = r1 / (1.0 + r1);
    if (delta < 0.25 || d >= max_differences || series.size() < 3) {
      const int p = -static_cast<int>(std::lround(2.0 * delta)) - 2 * d;
      return kind == SampleKind::kPhase ? p + 2 : p;
    }
    for (std::size_t i = 0; i + 1 < series.size(); ++i) series[i] = series[i + 1] - series[i];
    series.pop_back();
  }
}

double expected_b1_ratio(long long frequency_count, int mu) {
  const double n = static_cast<double>(frequency_count);
  if (mu == 0) return n * std::log(n) / (2.0 * (n - 1.0) * std::log(2.0));
  return n * (1.0 - std::pow(n, mu)) / (2.0 * (n - 1.0) * (1.0 - std::pow(2.0, mu)));
}

double expected_modified_ratio(int alpha, int m) {
  if (alpha == 2) return 1.0 / m;
  if (alpha == 1) return 3.37 / (1.04 + 3.0 * std::log(M_PI * m));
  throw std::invalid_argument("expected_modified_ratio: defined for alpha = 1 or 2, not " + std::to_string(alpha));
}

int estimate_noise_alpha(Statistic statistic, const std::vector<double>& phase, double tau0_s, int m, SampleKind kind) {
  const int order = difference_order(statistic);
  const int lowest_alpha = 2 - 2 * order;  // reddest noise it converges for: alpha + 2d > 1
  const std::vector<double> series = series_at_tau(phase, tau0_s, m, kind);
  int alpha = 0;
  if (static_cast<long long>(series.size()) >= kMinimumLag1Points) {
    alpha = lag1_autocorrelation_alpha(series, order, kind);
  } else {
    alpha = b1_fallback_alpha(statistic, phase, tau0_s, m, std::max(lowest_alpha, -2));
  }
  return std::clamp(alpha, lowest_alpha, 2);
}

}  // namespace allan
}  // namespace imu_lab
