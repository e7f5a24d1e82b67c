#include "imu_lab/identify/chi_squared.h"

#include <boost/math/distributions/chi_squared.hpp>

namespace imu_lab {
namespace identify {

double chi_squared_upper_tail(double statistic, double dof) {
  if (statistic <= 0.0) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), statistic));
}

double chi_squared_quantile(double probability, double dof) {
  return boost::math::quantile(boost::math::chi_squared(dof), probability);
}

}  // namespace identify
}  // namespace imu_lab
