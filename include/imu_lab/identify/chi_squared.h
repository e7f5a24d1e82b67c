// Chi-squared tail and quantile for the identification's tests: model selection compares the
// rise of the GMM distance with a chi-squared quantile, the profile bounds use one.
#pragma once

namespace imu_lab {
namespace identify {

// Upper tail P(chi2(dof) > statistic) and the quantile chi2(dof) at `probability`.
double chi_squared_upper_tail(double statistic, double dof);
double chi_squared_quantile(double probability, double dof);

}  // namespace identify
}  // namespace imu_lab
