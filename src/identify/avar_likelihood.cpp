#include "imu_lab/identify/avar_likelihood.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>

namespace imu_lab {
namespace identify {

namespace {
// u - 1 - ln u for u = 1 + e; the series avoids cancellation near e = 0.
double deviance_shape(double e) {
  if (std::abs(e) < 1e-3) return e * e * (0.5 - e / 3.0 + e * e / 4.0 - e * e * e / 5.0);
  return e - std::log1p(e);
}
}  // namespace

double point_deviance(double measured_avar, double model_avar, double edf) {
  return edf * deviance_shape(measured_avar / model_avar - 1.0);
}

DevianceResidual deviance_residual(double measured_avar, double model_avar, double edf) {
  const double u = measured_avar / model_avar;
  const double e = u - 1.0;
  const double root = std::sqrt(edf * deviance_shape(e));
  DevianceResidual residual;
  residual.value = e < 0.0 ? -root : root;
  double derivative_wrt_u;
  if (std::abs(e) < 1e-6) {
    derivative_wrt_u = std::sqrt(edf / 2.0) / ((1.0 + e) * std::sqrt(1.0 - 2.0 * e / 3.0));
  } else {
    derivative_wrt_u = edf * (e / u) / (2.0 * root) * (e < 0.0 ? -1.0 : 1.0);
  }
  residual.derivative_wrt_log_model = -u * derivative_wrt_u;  // du / d ln(model) = -u
  return residual;
}

double chi_squared_upper_tail(double statistic, double dof) {
  if (statistic <= 0.0) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), statistic));
}

double chi_squared_quantile(double probability, double dof) {
  return boost::math::quantile(boost::math::chi_squared(dof), probability);
}

}  // namespace identify
}  // namespace imu_lab
