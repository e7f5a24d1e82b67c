#include "imu_lab/identify/fit_problem.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "imu_lab/identify/avar_likelihood.h"

namespace imu_lab {
namespace identify {

namespace {

constexpr double kShapeStep = 1e-4;  // central-difference step in ln(shape)

// Residuals of all points in one block; the Jacobian is analytic in the amplitudes (AVAR is
// proportional to amplitude^2) and a central difference in the shapes.
class AvarDevianceCost : public ceres::CostFunction {
 public:
  AvarDevianceCost(const std::vector<FitPoint>& points, const ModelStructure& structure)
      : points_(points), structure_(structure) {
    set_num_residuals(static_cast<int>(points.size()));
    mutable_parameter_block_sizes()->push_back(parameter_count(structure));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const int count = parameter_count(structure_);
    const std::vector<double> log_parameters(parameters[0], parameters[0] + count);
    const NoiseModel model = model_from_log_parameters(structure_, log_parameters);
    const double corner = structure_.white_rate_corner_hz;
    std::vector<double> contributions(model.terms.size());
    for (size_t k = 0; k < points_.size(); ++k) {
      const double tau = points_[k].tau_s;
      double total = 0.0;
      for (size_t i = 0; i < model.terms.size(); ++i) {
        contributions[i] = term_avar(model.terms[i], tau, corner);
        total += contributions[i];
      }
      if (!(total > 0.0) || !std::isfinite(total)) return false;
      const DevianceResidual r = deviance_residual(points_[k].avar, total, points_[k].edf);
      if (!std::isfinite(r.value) || !std::isfinite(r.derivative_wrt_log_model)) return false;
      residuals[k] = r.value;
      if (jacobians == nullptr || jacobians[0] == nullptr) continue;
      double* row = jacobians[0] + k * count;
      int index = 0;
      for (size_t i = 0; i < model.terms.size(); ++i) {
        row[index++] = r.derivative_wrt_log_model * 2.0 * contributions[i] / total;
        if (!structure_.slots[i].shape_free) continue;
        Term up = model.terms[i], down = model.terms[i];
        up.shape *= std::exp(kShapeStep);
        down.shape *= std::exp(-kShapeStep);
        const double d_contribution =
            (term_avar(up, tau, corner) - term_avar(down, tau, corner)) / (2.0 * kShapeStep);
        row[index++] = r.derivative_wrt_log_model * d_contribution / total;
      }
    }
    return true;
  }

 private:
  std::vector<FitPoint> points_;
  ModelStructure structure_;
};

void build_problem(ceres::Problem* problem, std::vector<double>* parameters,
                   const std::vector<FitPoint>& points, const ModelStructure& structure,
                   const SolverSettings& settings) {
  ceres::LossFunction* loss = nullptr;
  if (settings.robust_loss_scale > 0.0) loss = new ceres::HuberLoss(settings.robust_loss_scale);
  problem->AddResidualBlock(new AvarDevianceCost(points, structure), loss, parameters->data());
}

}  // namespace

void log_parameter_bounds(const ModelStructure& structure, const DataSpan& span,
                          std::vector<double>* lower, std::vector<double>* upper) {
  const double unbounded = std::numeric_limits<double>::infinity();
  lower->clear();
  upper->clear();
  for (const TermSlot& slot : structure.slots) {
    lower->push_back(-unbounded);
    upper->push_back(unbounded);
    if (!slot.shape_free) continue;
    double low = 0.0, high = 0.0;
    switch (slot.kind) {
      case TermKind::kMarkov:
        low = span.tau_min_s / 4.0;
        high = 2.0 * span.record_length_s;
        break;
      case TermKind::kSinusoid:
      case TermKind::kBiasInstability:
        low = 1.0 / span.record_length_s;
        high = 1.0 / (2.0 * span.tau0_s);
        break;
      default:  // zero-DC family beta
        low = span.tau0_s;
        high = span.record_length_s;
        break;
    }
    lower->push_back(std::log(low));
    upper->push_back(std::log(high));
  }
}

SolveOutcome solve_model(const std::vector<FitPoint>& points, const ModelStructure& structure,
                         const std::vector<double>& start, const DataSpan& span,
                         const SolverSettings& settings, const std::vector<int>& held_fixed) {
  std::vector<double> lower, upper;
  log_parameter_bounds(structure, span, &lower, &upper);
  std::vector<double> parameters = start;
  for (size_t i = 0; i < parameters.size(); ++i) {
    parameters[i] = std::min(std::max(parameters[i], lower[i]), upper[i]);
  }
  SolveOutcome outcome;
  ceres::Problem problem;
  build_problem(&problem, &parameters, points, structure, settings);
  for (size_t i = 0; i < parameters.size(); ++i) {
    if (std::isfinite(lower[i])) problem.SetParameterLowerBound(parameters.data(), i, lower[i]);
    if (std::isfinite(upper[i])) problem.SetParameterUpperBound(parameters.data(), i, upper[i]);
  }
  if (!held_fixed.empty()) {
    if (held_fixed.size() == parameters.size()) {
      outcome.log_parameters = parameters;
      outcome.cost = model_cost(points, structure, parameters, settings);
      outcome.usable = std::isfinite(outcome.cost);
      return outcome;
    }
    problem.SetManifold(parameters.data(),
                        new ceres::SubsetManifold(static_cast<int>(parameters.size()), held_fixed));
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = settings.max_iterations;
  options.function_tolerance = 1e-12;
  options.gradient_tolerance = 1e-12;
  options.parameter_tolerance = 1e-10;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  outcome.log_parameters = parameters;
  outcome.cost = summary.final_cost;
  outcome.usable = summary.IsSolutionUsable() && std::isfinite(summary.final_cost);
  return outcome;
}

double model_cost(const std::vector<FitPoint>& points, const ModelStructure& structure,
                  const std::vector<double>& log_parameters, const SolverSettings& settings) {
  const NoiseModel model = model_from_log_parameters(structure, log_parameters);
  double cost = 0.0;
  for (const FitPoint& point : points) {
    const double model_value = model_avar(model, point.tau_s);
    if (!(model_value > 0.0)) return std::numeric_limits<double>::infinity();
    const double r2 = point_deviance(point.avar, model_value, point.edf);
    const double a = settings.robust_loss_scale;
    const double rho = (a > 0.0 && r2 > a * a) ? 2.0 * a * std::sqrt(r2) - a * a : r2;
    cost += 0.5 * rho;
  }
  return cost;
}

bool log_parameter_covariance(const std::vector<FitPoint>& points, const ModelStructure& structure,
                              const std::vector<double>& log_parameters,
                              const SolverSettings& settings, Eigen::MatrixXd* covariance) {
  std::vector<double> parameters = log_parameters;
  ceres::Problem problem;
  build_problem(&problem, &parameters, points, structure, settings);
  ceres::Covariance::Options options;
  options.algorithm_type = ceres::DENSE_SVD;
  options.null_space_rank = -1;
  options.min_reciprocal_condition_number = 1e-14;
  options.num_threads = 1;
  ceres::Covariance estimator(options);
  std::vector<std::pair<const double*, const double*>> blocks = {
      {parameters.data(), parameters.data()}};
  if (!estimator.Compute(blocks, &problem)) return false;
  const int n = static_cast<int>(parameters.size());
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> values(n, n);
  if (!estimator.GetCovarianceBlock(parameters.data(), parameters.data(), values.data())) {
    return false;
  }
  *covariance = values;
  return true;
}

}  // namespace identify
}  // namespace imu_lab
