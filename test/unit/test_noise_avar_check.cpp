#include "test_noise_avar_check.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <memory>
#include <numeric>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/edf.h"

namespace imu_lab {
namespace test {

namespace {
// Power-law exponent of the frequency PSD matching the local AVAR slope mu (AVAR ~ tau^mu),
// mu = -alpha - 1; slopes steeper than -1.5 are white phase (alpha = 2).
int local_alpha(const std::function<double(double)>& expected, double tau) {
  const double mu = std::log(expected(tau * std::sqrt(2.0)) / expected(tau / std::sqrt(2.0))) / std::log(2.0);
  if (mu < -1.5) return 2;
  return std::max(-2, std::min(1, static_cast<int>(std::lround(-mu - 1.0))));
}
}  // namespace

double exact_overlapping_edf(const std::function<double(long)>& structure, int m, std::size_t rate_count,
                             long correlation_samples) {
  const long terms = static_cast<long>(rate_count) + 1 - 2L * m;  // M second differences
  const double weights[3] = {1.0, -2.0, 1.0};
  auto gamma = [&](long j) {
    double sum = 0.0;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) sum += weights[p] * weights[q] * structure(std::labs(j + (p - q) * m));
    return -0.5 * sum;
  };
  const long last = std::min(terms - 1, 2L * m + correlation_samples);
  const double gamma_0 = gamma(0);
  double sum = terms * gamma_0 * gamma_0;
  for (long j = 1; j <= last; ++j) {
    const double g = gamma(j);
    sum += 2.0 * (terms - j) * g * g;
  }
  return static_cast<double>(terms) * terms * gamma_0 * gamma_0 / sum;
}

EdfOfFactor power_law_edf(const std::function<double(double)>& stochastic, double tau0) {
  return [=](int m, std::size_t count) {
    return allan::equivalent_degrees_of_freedom(allan::Statistic::kOverlappingAllan, local_alpha(stochastic, m * tau0),
                                                m, static_cast<long long>(count + 1));
  };
}

EdfOfFactor stationary_angle_edf(const std::function<double(double)>& covariance, double tau0, long correlation_samples,
                                 int max_factor) {
  auto structure =
      std::make_shared<std::vector<double>>(4 * static_cast<std::size_t>(max_factor) + correlation_samples + 1);
  const double c0 = covariance(0.0);
  for (std::size_t j = 0; j < structure->size(); ++j) (*structure)[j] = 2.0 * (c0 - covariance(j * tau0));
  return [structure, correlation_samples](int m, std::size_t count) {
    return exact_overlapping_edf([&](long j) { return (*structure)[j]; }, m, count, correlation_samples);
  };
}

double numerical_avar(const std::function<double(double)>& psd, double tau, double f_max) {
  constexpr double kPi = 3.14159265358979323846;
  const double step = 1.0 / tau;
  double sum = 0.0;
  for (double f = 0.0; f < f_max; f += step) {
    sum += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
        [&](double x) {
          if (x <= 0.0) return 0.0;
          const double s = std::sin(kPi * x * tau);
          return 4.0 * psd(x) * s * s * s * s / ((kPi * x * tau) * (kPi * x * tau));
        },
        f, std::min(f + step, f_max), 3, 1e-12);
  }
  return sum;
}

std::vector<double> collect(std::size_t count, const std::function<double()>& sample) {
  std::vector<double> values(count);
  for (auto& value : values) value = sample();
  return values;
}

AvarCheck check_avar(const std::vector<double>& rates, double tau0, const std::function<double(double)>& expected,
                     int m_min, int m_max, double family_confidence, const EdfOfFactor& exact_edf) {
  // Remove the mean before integrating so the phase keeps its precision (doc/models.md).
  const double mean = std::accumulate(rates.begin(), rates.end(), 0.0) / rates.size();
  std::vector<double> centred(rates.size());
  std::transform(rates.begin(), rates.end(), centred.begin(), [&](double r) { return r - mean; });
  const std::vector<double> phase = allan::phase_from_frequency(centred, tau0);

  std::vector<int> factors;
  for (int m = m_min; m <= m_max; m *= 2) factors.push_back(m);
  AvarCheck check;
  check.point_count = static_cast<int>(factors.size());
  check.per_point_level = (1.0 - family_confidence) / check.point_count;
  for (int m : factors) {
    const double tau = m * tau0;
    const double measured = allan::overlapping_allan_variance(phase, tau0, m);
    const double truth = expected(tau);
    const int alpha = local_alpha(expected, tau);
    const double edf = exact_edf ? exact_edf(m, rates.size())
                                 : allan::equivalent_degrees_of_freedom(allan::Statistic::kOverlappingAllan, alpha, m,
                                                                        static_cast<long long>(phase.size()));
    const boost::math::chi_squared distribution(edf);
    const double low = boost::math::quantile(distribution, check.per_point_level / 2.0) / edf;
    const double high = boost::math::quantile(distribution, 1.0 - check.per_point_level / 2.0) / edf;
    const double ratio = measured / truth;
    const bool rejected = ratio < low || ratio > high;
    const double normalised = std::abs(ratio - 1.0) / std::sqrt(2.0 / edf);
    if (normalised > check.worst_normalised_deviation) {
      check.worst_normalised_deviation = normalised;
      check.worst_ratio = ratio;
    }
    check.rejected_points += rejected ? 1 : 0;
    char line[200];
    std::snprintf(line, sizeof line, "tau %10.4g s  ratio %8.4f  bounds [%6.3f, %6.3f]  edf %9.1f  alpha %2d%s\n", tau,
                  ratio, low, high, edf, alpha, rejected ? "  REJECTED" : "");
    check.table += line;
  }
  return check;
}

}  // namespace test
}  // namespace imu_lab
