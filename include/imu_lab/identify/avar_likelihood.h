// Likelihood of one measured AVAR point: the estimate is distributed as AVAR * chi2(edf) / edf
// (the EDF model of NIST SP 1065), so with u = measured / model
//   -log L = (edf / 2) (u + ln model) + const,   deviance d = edf (u - 1 - ln u) >= 0,
// and half the summed deviance is the negative log-likelihood up to a constant. Its minimum is at
// model = measured, so it is unbiased, unlike a least-squares fit of log AVAR (E ln chi2/edf < 0).
#pragma once

namespace imu_lab {
namespace identify {

double point_deviance(double measured_avar, double model_avar, double edf);

// Signed root of the deviance, r = sign(u - 1) sqrt(d), and dr / d(ln model): r^2 = d, and near
// u = 1, r ~ sqrt(edf / 2) (u - 1) is a standard normal residual.
struct DevianceResidual {
  double value = 0.0;
  double derivative_wrt_log_model = 0.0;
};
DevianceResidual deviance_residual(double measured_avar, double model_avar, double edf);

// Upper tail P(chi2(dof) > statistic) and the quantile chi2(dof) at `probability`.
double chi_squared_upper_tail(double statistic, double dof);
double chi_squared_quantile(double probability, double dof);

}  // namespace identify
}  // namespace imu_lab
