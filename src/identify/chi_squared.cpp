#include "imu_lab/identify/chi_squared.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/special_functions/digamma.hpp>
#include <boost/math/special_functions/trigamma.hpp>
#include <cmath>

namespace imu_lab {
namespace identify {

double chi_squared_upper_tail(double statistic, double dof) {
  if (statistic <= 0.0) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), statistic));
}

double chi_squared_quantile(double probability, double dof) {
  return boost::math::quantile(boost::math::chi_squared(dof), probability);
}

double mean_log_scaled_chi_squared(double edf) {
  if (!(edf > 0.0)) return 0.0;
  // E ln(chi2_e / e) = digamma(e / 2) - ln(e / 2); its asymptotic series beyond e = 200.
  if (edf > 200.0) return -1.0 / edf - 1.0 / (3.0 * edf * edf);
  return boost::math::digamma(0.5 * edf) - std::log(0.5 * edf);
}

double variance_log_scaled_chi_squared(double edf) {
  if (!(edf > 0.0)) return 0.0;
  // trigamma(e / 2); its asymptotic series beyond e = 200, as the mean's.
  if (edf > 200.0) return 2.0 / edf + 2.0 / (edf * edf) + 4.0 / (3.0 * edf * edf * edf);
  return boost::math::trigamma(0.5 * edf);
}

}  // namespace identify
}  // namespace imu_lab
