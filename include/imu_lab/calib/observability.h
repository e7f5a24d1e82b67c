// What a calibration problem can tell: from the noise-weighted Jacobian J (residuals divided by
// their sigmas), the condition number of J with its columns scaled to unit length, the parameter
// combinations J cannot see (null-space directions, named), and the covariance (J^T J)^-1.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace imu_lab {
namespace calib {

struct Observability {
  double condition_number = 0.0;  // of the column-scaled J; infinity when rank-deficient
  // One entry per null-space direction: the parameters it moves, largest share first.
  std::vector<std::vector<std::string>> unobservable;
  Eigen::MatrixXd covariance;  // (J^T J)^-1 (pseudo-inverse when rank-deficient), unit residual variance
};

// relative_tolerance: a scaled singular value below this times the largest counts as zero.
Observability analyse_observability(const Eigen::MatrixXd& weighted_jacobian,
                                    const std::vector<std::string>& column_names, double relative_tolerance = 1e-9);

}  // namespace calib
}  // namespace imu_lab
