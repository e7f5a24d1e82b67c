// Chi-squared tail and quantile for the identification's tests (model selection compares the
// rise of the GMM distance with a chi-squared quantile, the profile bounds use one), and the law
// of ln(chi2_e / e), the log of an AVAR estimate over its expectation at e equivalent degrees of
// freedom, on which the fit's moments live (fit_problem.h).
#pragma once

namespace imu_lab {
namespace identify {

// Upper tail P(chi2(dof) > statistic) and the quantile chi2(dof) at `probability`.
double chi_squared_upper_tail(double statistic, double dof);
double chi_squared_quantile(double probability, double dof);

// E ln(chi2_e / e) = digamma(e / 2) - ln(e / 2).
double mean_log_scaled_chi_squared(double edf);
// var ln(chi2_e / e) = trigamma(e / 2): 2 / e to first order, 1.64 times that at e = 2 and 2.47
// times at e = 1.
double variance_log_scaled_chi_squared(double edf);

}  // namespace identify
}  // namespace imu_lab
