#include "imu_lab/calib/observability.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace imu_lab {
namespace calib {

Observability analyse_observability(const Eigen::MatrixXd& weighted_jacobian,
                                    const std::vector<std::string>& column_names, double relative_tolerance) {
  const Eigen::Index columns = weighted_jacobian.cols();
  // Column scaling: units (ppm against m/s^2 against radians) must not decide the condition.
  Eigen::VectorXd column_norms = weighted_jacobian.colwise().norm().transpose();
  for (Eigen::Index c = 0; c < columns; ++c) {
    if (column_norms[c] == 0.0) column_norms[c] = 1.0;
  }
  const Eigen::MatrixXd scaled = weighted_jacobian * column_norms.cwiseInverse().asDiagonal();
  // Full V: a problem with fewer residuals than parameters has null directions beyond the thin SVD.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeFullV);
  Eigen::VectorXd singular = Eigen::VectorXd::Zero(columns);
  singular.head(svd.singularValues().size()) = svd.singularValues();
  const double largest = singular.maxCoeff();

  Observability result;
  Eigen::MatrixXd inverse_information = Eigen::MatrixXd::Zero(columns, columns);
  for (Eigen::Index k = 0; k < columns; ++k) {
    const Eigen::VectorXd direction = svd.matrixV().col(k);
    if (singular[k] > relative_tolerance * largest) {
      inverse_information += direction * direction.transpose() / (singular[k] * singular[k]);
      continue;
    }
    std::vector<Eigen::Index> order(columns);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](Eigen::Index a, Eigen::Index b) { return std::abs(direction[a]) > std::abs(direction[b]); });
    std::vector<std::string> names;
    for (Eigen::Index c : order) {
      if (std::abs(direction[c]) < 0.2) break;
      names.push_back(column_names[c]);
    }
    result.unobservable.push_back(names);
  }
  const double smallest = singular.minCoeff();
  result.condition_number =
      smallest > relative_tolerance * largest ? largest / smallest : std::numeric_limits<double>::infinity();
  const Eigen::VectorXd unscale = column_norms.cwiseInverse();
  result.covariance = unscale.asDiagonal() * inverse_information * unscale.asDiagonal();
  return result;
}

}  // namespace calib
}  // namespace imu_lab
