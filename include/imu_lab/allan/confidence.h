// Chi-squared confidence bounds of a deviation with a given number of degrees of freedom.
#pragma once

namespace imu_lab {
namespace allan {

struct DeviationBounds {
  double lower = 0.0;
  double upper = 0.0;
};

// Two-sided bounds holding `confidence` (e.g. 0.683) of the probability:
//   sigma_lower = sigma * sqrt(edf / chi2((1 + confidence) / 2, edf))
//   sigma_upper = sigma * sqrt(edf / chi2((1 - confidence) / 2, edf))
// (NIST SP 1065, eq. 45), with exact chi-squared quantiles from Boost.Math (Wilson-Hilferty
// from 1e8 degrees of freedom on, within 5e-14 of them, where Boost's series stops converging).
// Throws std::invalid_argument for edf <= 0, confidence outside (0, 1) or deviation < 0.
DeviationBounds chi_squared_bounds(double deviation, double edf, double confidence);

}  // namespace allan
}  // namespace imu_lab
