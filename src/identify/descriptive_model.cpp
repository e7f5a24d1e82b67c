#include "imu_lab/identify/descriptive_model.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace imu_lab {
namespace identify {

Eigen::VectorXd non_negative_least_squares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const int n = static_cast<int>(a.cols());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(n, false);
  const double tolerance = 1e-12 * a.norm() * b.norm();
  const auto solve_passive = [&]() {
    std::vector<int> columns;
    for (int j = 0; j < n; ++j) {
      if (passive[j]) columns.push_back(j);
    }
    Eigen::MatrixXd reduced(a.rows(), columns.size());
    for (size_t k = 0; k < columns.size(); ++k) reduced.col(k) = a.col(columns[k]);
    const Eigen::VectorXd solution = reduced.colPivHouseholderQr().solve(b);
    Eigen::VectorXd full = Eigen::VectorXd::Zero(n);
    for (size_t k = 0; k < columns.size(); ++k) full(columns[k]) = solution(k);
    return full;
  };
  for (int outer = 0; outer < 3 * n; ++outer) {
    const Eigen::VectorXd gradient = a.transpose() * (b - a * x);
    int entering = -1;
    double largest = tolerance;
    for (int j = 0; j < n; ++j) {
      if (!passive[j] && gradient(j) > largest) {
        largest = gradient(j);
        entering = j;
      }
    }
    if (entering < 0) break;
    passive[entering] = true;
    for (int inner = 0; inner < 3 * n; ++inner) {
      const Eigen::VectorXd z = solve_passive();
      bool feasible = true;
      for (int j = 0; j < n; ++j) feasible = feasible && (!passive[j] || z(j) > 0.0);
      if (feasible) {
        x = z;
        break;
      }
      double step = 1.0;
      for (int j = 0; j < n; ++j) {
        if (passive[j] && z(j) <= 0.0) step = std::min(step, x(j) / (x(j) - z(j)));
      }
      x += step * (z - x);
      for (int j = 0; j < n; ++j) {
        if (passive[j] && x(j) <= 1e-300) {
          passive[j] = false;
          x(j) = 0.0;
        }
      }
    }
  }
  return x;
}

NoiseModel descriptive_model(const std::vector<FitPoint>& points, const DataSpan& span,
                             double output_quantization_density) {
  NoiseModel model;
  model.output_quantization_density = output_quantization_density;
  // Unit-amplitude candidates: white rate, and Markov terms from a quarter of tau0 (a front end)
  // to twice the record, half an octave apart.
  std::vector<Term> candidates = {{TermKind::kWhiteRate, 1.0, 0.0, 0.0}};
  for (double correlation_time_s = span.tau0_s / 4.0; correlation_time_s < 2.0 * span.record_length_s;
       correlation_time_s *= std::sqrt(2.0)) {
    candidates.push_back({TermKind::kMarkov, 1.0, correlation_time_s, 0.0});
  }
  const int rows = static_cast<int>(points.size());
  Eigen::MatrixXd design(rows, candidates.size());
  Eigen::VectorXd target(rows);
  for (int k = 0; k < rows; ++k) {
    const double quantization = model_avar(NoiseModel{{}, output_quantization_density}, points[k].tau_s);
    target(k) = std::max(0.0, points[k].avar - quantization) / points[k].avar;
    for (size_t j = 0; j < candidates.size(); ++j)
      design(k, j) = term_avar(candidates[j], points[k].tau_s) / points[k].avar;
  }
  // Columns scaled to unit norm so the solver's tolerances are scale-free.
  Eigen::VectorXd norms = design.colwise().norm().transpose();
  for (int j = 0; j < norms.size(); ++j) {
    if (norms(j) > 0.0) design.col(j) /= norms(j);
  }
  const Eigen::VectorXd squared = non_negative_least_squares(design, target);
  for (size_t j = 0; j < candidates.size(); ++j) {
    if (!(squared(j) > 0.0) || !(norms(j) > 0.0)) continue;
    Term term = candidates[j];
    term.amplitude = std::sqrt(squared(j) / norms(j));
    model.terms.push_back(term);
  }
  return model;
}

}  // namespace identify
}  // namespace imu_lab
