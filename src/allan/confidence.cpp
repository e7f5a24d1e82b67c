// Chi-squared bounds of a deviation (NIST SP 1065, eq. 45).
#include "imu_lab/allan/confidence.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <boost/math/distributions/chi_squared.hpp>

namespace imu_lab {
namespace allan {

DeviationBounds chi_squared_bounds(double deviation, double edf, double confidence) {
  if (!(edf > 0.0) || !std::isfinite(edf)) {
    throw std::invalid_argument("chi_squared_bounds: edf = " + std::to_string(edf) +
                                " must be positive and finite");
  }
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw std::invalid_argument("chi_squared_bounds: confidence = " +
                                std::to_string(confidence) +
                                " must lie strictly between 0 and 1 (e.g. 0.683)");
  }
  if (!(deviation >= 0.0)) {
    throw std::invalid_argument("chi_squared_bounds: deviation = " + std::to_string(deviation) +
                                " must be non-negative");
  }
  const boost::math::chi_squared_distribution<double> chi_squared(edf);
  const double tail = (1.0 - confidence) / 2.0;
  const double chi2_high = boost::math::quantile(chi_squared, 1.0 - tail);
  const double chi2_low = boost::math::quantile(chi_squared, tail);
  return {deviation * std::sqrt(edf / chi2_high), deviation * std::sqrt(edf / chi2_low)};
}

}  // namespace allan
}  // namespace imu_lab
