// Equivalent degrees of freedom, Greenhall & Riley (PTTI 2003) and NIST SP 1065.
#include "imu_lab/allan/edf.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace imu_lab {
namespace allan {
namespace {

constexpr double kInfiniteFilter = std::numeric_limits<double>::infinity();
constexpr int kJMax = 100;  // Greenhall's suggested cut-off for the explicit sum
// sx() takes a second difference with step 1/m: its round-off grows as eps * m^2, while the
// F = infinity limit it tends to is already within ~1e-5 at m = 1e4.
constexpr int kLargestFiniteFilter = 10000;

// Generalised autocovariance of the continuous pure power-law process w with exponent alpha
// (Greenhall & Riley eq. 7), up to a constant factor that cancels in the EDF ratio.
double sw(double t, int alpha) {
  const double a = std::fabs(t);
  const double log_a = a > 0.0 ? std::log(a) : 0.0;
  switch (alpha) {
    case 2: return -a;
    case 1: return a * a * log_a;
    case 0: return a * a * a;
    case -1: return -a * a * a * a * log_a;
    case -2: return -a * a * a * a * a;
    case -3: return a * a * a * a * a * a * log_a;
    case -4: return a * a * a * a * a * a * a;
  }
  throw std::invalid_argument("greenhall_edf: noise exponent alpha = " + std::to_string(alpha) +
                              " is outside 2 ... -4");
}

// Autocovariance of the (averaged) phase samples, filter factor F (eq. 8).
double sx(double t, double filter_factor, int alpha) {
  if (std::isinf(filter_factor)) return sw(t, alpha + 2);
  const double step = 1.0 / filter_factor;
  return filter_factor * filter_factor * (2.0 * sw(t, alpha) - sw(t - step, alpha) - sw(t + step, alpha));
}

double binomial(int n, int k) {
  double value = 1.0;
  for (int i = 1; i <= k; ++i) value = value * (n - k + i) / i;
  return value;
}

// Autocovariance of the d-th differences (eq. 9): sum_k (-1)^k C(2d, d+k) sx(t + k).
double sz(double t, double filter_factor, int alpha, int d) {
  double value = 0.0;
  for (int k = -d; k <= d; ++k) {
    const double sign = (k % 2 == 0) ? 1.0 : -1.0;
    value += sign * binomial(2 * d, d + k) * sx(t + k, filter_factor, alpha);
  }
  return value;
}

// Eq. 10: sz(0)^2 + (1 - J/M) sz(J/S)^2 + 2 sum_{j=1}^{J-1} (1 - j/M) sz(j/S)^2.
double basic_sum(double j_count, double summands, double stride, double filter_factor, int alpha, int d) {
  const double at_zero = sz(0.0, filter_factor, alpha, d);
  const double at_end = sz(j_count / stride, filter_factor, alpha, d);
  double sum = at_zero * at_zero + (1.0 - j_count / summands) * at_end * at_end;
  for (int j = 1; j < static_cast<int>(j_count); ++j) {
    const double value = sz(j / stride, filter_factor, alpha, d);
    sum += 2.0 * (1.0 - j / summands) * value * value;
  }
  return sum;
}

struct Coefficients {
  double first;
  double second;
};

// Large-r asymptotes 1/edf ~ (a0 - a1/r)/r, Greenhall & Riley tables 1 (modified) and
// 2 (unmodified), rows alpha = 2 ... -4, columns d = 1, 2, 3; {0, 0} where alpha + 2d <= 1.
Coefficients asymptote(bool modified, int alpha, int d) {
  static const Coefficients kModified[7][3] = {{{2.0 / 3.0, 1.0 / 3.0}, {7.0 / 9.0, 0.5}, {22.0 / 25.0, 2.0 / 3.0}},
                                               {{0.840, 0.345}, {0.997, 0.616}, {1.141, 0.843}},
                                               {{1.079, 0.368}, {1.033, 0.607}, {1.184, 0.848}},
                                               {{0.0, 0.0}, {1.048, 0.534}, {1.180, 0.816}},
                                               {{0.0, 0.0}, {1.302, 0.535}, {1.175, 0.777}},
                                               {{0.0, 0.0}, {0.0, 0.0}, {1.194, 0.703}},
                                               {{0.0, 0.0}, {0.0, 0.0}, {1.489, 0.702}}};
  static const Coefficients kUnmodified[7][3] = {{{1.5, 0.5}, {35.0 / 18.0, 1.0}, {2.31, 1.5}},
                                                 {{78.6, 25.2}, {790.0, 410.0}, {9950.0, 6520.0}},
                                                 {{2.0 / 3.0, 1.0 / 6.0}, {2.0 / 3.0, 1.0 / 3.0}, {7.0 / 9.0, 0.5}},
                                                 {{0.0, 0.0}, {0.852, 0.375}, {0.997, 0.617}},
                                                 {{0.0, 0.0}, {1.079, 0.368}, {1.033, 0.607}},
                                                 {{0.0, 0.0}, {0.0, 0.0}, {1.053, 0.553}},
                                                 {{0.0, 0.0}, {0.0, 0.0}, {1.302, 0.535}}};
  return (modified ? kModified : kUnmodified)[2 - alpha][d - 1];
}

// Table 3: the FPM (alpha = 1) normalisation sz(0) ~ b0 + b1 ln m of unmodified variances.
Coefficients flicker_phase_normalisation(int d) {
  static const Coefficients kTable3[3] = {{6.0, 4.0}, {15.23, 12.0}, {47.8, 40.0}};
  return kTable3[d - 1];
}

}  // namespace

double greenhall_edf(int alpha, int difference_order, int m, long long phase_count, bool overlapping, bool modified) {
  const int d = difference_order;
  if (d < 1 || d > 3 || alpha > 2 || alpha < -4 || alpha + 2 * d <= 1) {
    throw std::invalid_argument("greenhall_edf: a difference order d = " + std::to_string(d) +
                                " estimator cannot handle noise exponent alpha = " + std::to_string(alpha) +
                                " (needs alpha + 2d > 1, d in 1..3)");
  }
  if (m < 1) throw std::invalid_argument("greenhall_edf: averaging factor m must be >= 1");
  const double filter_factor = modified ? 1.0 : m;  // F
  const double stride = overlapping ? m : 1.0;      // S: estimator stride is tau / S
  // L = m/F + m d: the number of phase samples one term of the estimator spans.
  const long long span = (modified ? static_cast<long long>(m) : 1LL) + static_cast<long long>(m) * d;
  if (phase_count < span) {
    throw std::invalid_argument("greenhall_edf: " + std::to_string(phase_count) +
                                " phase samples are fewer than the filter length " + std::to_string(span) +
                                " at m = " + std::to_string(m));
  }
  // M: number of summands; J: terms in the explicit autocovariance sum; r = M / S.
  const double summands = 1.0 + std::floor(stride * static_cast<double>(phase_count - span) / m);
  const double j_count = std::min(summands, (d + 1) * stride);
  const double r = summands / stride;

  if (modified) {  // case 1: F = 1, all alpha
    if (j_count <= kJMax) {
      const double at_zero = sz(0.0, 1.0, alpha, d);
      return at_zero * at_zero * summands / basic_sum(j_count, summands, stride, 1.0, alpha, d);
    }
    if (r > d + 1) {
      const Coefficients c = asymptote(true, alpha, d);
      return r / (c.first - c.second / r);
    }
    const double at_zero = sz(0.0, 1.0, alpha, d);
    return at_zero * at_zero * kJMax / basic_sum(kJMax, kJMax, kJMax / r, 1.0, alpha, d);
  }
  if (alpha <= 0) {  // case 2: unmodified, WFM and redder
    if (j_count <= kJMax) {
      // Greenhall switches to F = infinity once m (d + 1) > J_max; Stable32 keeps the exact
      // F = m (its bounds at PHASE.DAT m = 64, 128 show it), which we follow until the
      // second differences inside sx() would lose precision to the 1/m step.
      const double filter = m <= kLargestFiniteFilter ? filter_factor : kInfiniteFilter;
      const double at_zero = sz(0.0, filter, alpha, d);
      return at_zero * at_zero * summands / basic_sum(j_count, summands, stride, filter, alpha, d);
    }
    if (r > d + 1) {
      const Coefficients c = asymptote(false, alpha, d);
      return r / (c.first - c.second / r);
    }
    const double at_zero = sz(0.0, kInfiniteFilter, alpha, d);
    return at_zero * at_zero * kJMax / basic_sum(kJMax, kJMax, kJMax / r, kInfiniteFilter, alpha, d);
  }
  if (alpha == 1) {  // case 3: unmodified FPM, logarithmic in m
    const Coefficients b = flicker_phase_normalisation(d);
    const double log_normalisation = b.first + b.second * std::log(static_cast<double>(m));
    if (j_count <= kJMax) {
      const double at_zero = sz(0.0, filter_factor, alpha, d);
      return at_zero * at_zero * summands / basic_sum(j_count, summands, stride, filter_factor, alpha, d);
    }
    if (r > d + 1) {
      const Coefficients c = asymptote(false, alpha, d);
      return log_normalisation * log_normalisation * r / (c.first - c.second / r);
    }
    const double m_prime = kJMax / r;
    return log_normalisation * log_normalisation * kJMax / basic_sum(kJMax, kJMax, m_prime, m_prime, alpha, d);
  }
  // case 4: unmodified WPM; the differences are correlated over d lags only.
  const double k_ceiling = std::ceil(r);
  if (k_ceiling <= d) {
    const double centre = binomial(2 * d, d);
    double sum = 1.0;
    for (int k = 1; k < static_cast<int>(k_ceiling); ++k) {
      const double weight = binomial(2 * d, d - k);
      sum += 2.0 * (1.0 - k / r) * weight * weight / (centre * centre);
    }
    return summands / sum;
  }
  const Coefficients c = asymptote(false, alpha, d);
  return summands / (c.first - c.second / r);
}

double total_variance_edf(int alpha, int m, long long phase_count) {
  if (alpha > 0) return greenhall_edf(alpha, 2, m, phase_count, true, false);
  static const Coefficients kTotal[3] = {{1.50, 0.0}, {1.17, 0.22}, {0.93, 0.36}};
  const Coefficients c = kTotal[std::min(-alpha, 2)];
  // T / tau with T = N tau0 for N phase samples: the count Stable32's bounds reproduce.
  const double record_in_taus = static_cast<double>(phase_count) / m;
  return c.first * record_in_taus - c.second;
}

double equivalent_degrees_of_freedom(Statistic statistic, int alpha, int m, long long phase_count) {
  // Greenhall's algorithm needs alpha + 2d > 1.
  const int resolved_alpha = std::max(alpha, 2 - 2 * difference_order(statistic));
  switch (statistic) {
    case Statistic::kAllan: return greenhall_edf(resolved_alpha, 2, m, phase_count, false, false);
    case Statistic::kOverlappingAllan: return greenhall_edf(resolved_alpha, 2, m, phase_count, true, false);
    case Statistic::kModifiedAllan:
    case Statistic::kTime: return greenhall_edf(resolved_alpha, 2, m, phase_count, true, true);
    case Statistic::kHadamard: return greenhall_edf(resolved_alpha, 3, m, phase_count, false, false);
    case Statistic::kOverlappingHadamard: return greenhall_edf(resolved_alpha, 3, m, phase_count, true, false);
    case Statistic::kTotal: return total_variance_edf(resolved_alpha, m, phase_count);
    case Statistic::kAllanKrobka: return greenhall_edf(resolved_alpha, 2, m, phase_count, true, false) - 1.0;
    case Statistic::kHadamardKrobka: return greenhall_edf(resolved_alpha, 3, m, phase_count, true, false) - 1.0;
  }
  throw std::invalid_argument("equivalent_degrees_of_freedom: unknown statistic");
}

}  // namespace allan
}  // namespace imu_lab
