#include "test_noise_avar_check.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/edf.h"

namespace imu_lab {
namespace test {

namespace {
// Power-law exponent of the frequency PSD matching the local AVAR slope mu (AVAR ~ tau^mu),
// mu = -alpha - 1; slopes steeper than -1.5 are white phase (alpha = 2).
int local_alpha(const std::function<double(double)>& expected, double tau) {
  const double mu = std::log(expected(tau * std::sqrt(2.0)) / expected(tau / std::sqrt(2.0))) /
                    std::log(2.0);
  if (mu < -1.5) return 2;
  return std::max(-2, std::min(1, static_cast<int>(std::lround(-mu - 1.0))));
}
}  // namespace

std::vector<double> collect(std::size_t count, const std::function<double()>& sample) {
  std::vector<double> values(count);
  for (auto& value : values) value = sample();
  return values;
}

AvarCheck check_avar(const std::vector<double>& rates, double tau0, 
                     const std::function<double(double)>& expected, int m_min, int m_max,
                     double family_confidence) {
  // Remove the mean before integrating so the phase keeps its precision (DESIGN.md 5).
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
    const double edf = allan::equivalent_degrees_of_freedom(
        allan::Statistic::kOverlappingAllan, alpha, m, static_cast<long long>(phase.size()));
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
    std::snprintf(line, sizeof line, "tau %10.4g s  ratio %8.4f  bounds [%6.3f, %6.3f]  edf %9.1f  alpha %2d%s\n",
                  tau, ratio, low, high, edf, alpha, rejected ? "  REJECTED" : "");
    check.table += line;
  }
  return check;
}

}  // namespace test
}  // namespace imu_lab
