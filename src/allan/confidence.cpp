// Chi-squared bounds of a deviation (NIST SP 1065, eq. 45).
#include "imu_lab/allan/confidence.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>

namespace imu_lab {
namespace allan {
namespace {

// Boost's series for the chi-squared quantile gives up somewhere between 1e9 and 1e12 degrees
// of freedom. From 1e8 on, Wilson and Hilferty's cube-of-a-normal approximation agrees with
// Boost to 5e-14 relative (at the 68.3 % and 95 % tails), so it takes over there.
constexpr double kWilsonHilfertyMinimumEdf = 1e8;

double chi_squared_quantile(double probability, double edf) {
  if (edf < kWilsonHilfertyMinimumEdf) {
    return boost::math::quantile(boost::math::chi_squared_distribution<double>(edf), probability);
  }
  const double z = boost::math::quantile(boost::math::normal_distribution<double>(), probability);
  const double variance = 2.0 / (9.0 * edf);
  const double cube_root = 1.0 - variance + z * std::sqrt(variance);
  return edf * cube_root * cube_root * cube_root;
}

}  // namespace

DeviationBounds chi_squared_bounds(double deviation, double edf, double confidence) {
  if (!(edf > 0.0) || !std::isfinite(edf)) {
    throw std::invalid_argument("chi_squared_bounds: edf = " + std::to_string(edf) + " must be positive and finite");
  }
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw std::invalid_argument("chi_squared_bounds: confidence = " + std::to_string(confidence) +
                                " must lie strictly between 0 and 1 (e.g. 0.683)");
  }
  if (!(deviation >= 0.0)) {
    throw std::invalid_argument("chi_squared_bounds: deviation = " + std::to_string(deviation) +
                                " must be non-negative");
  }
  const double tail = (1.0 - confidence) / 2.0;
  const double chi2_high = chi_squared_quantile(1.0 - tail, edf);
  const double chi2_low = chi_squared_quantile(tail, edf);
  return {deviation * std::sqrt(edf / chi2_high), deviation * std::sqrt(edf / chi2_low)};
}

}  // namespace allan
}  // namespace imu_lab
