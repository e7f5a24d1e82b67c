#include "imu_lab/identify/fit_problem.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "imu_lab/common/cancellation.h"
#include "imu_lab/common/ceres_solver_options.h"
#include "imu_lab/identify/chi_squared.h"
#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace identify {

namespace {

constexpr double kShapeStep = 1e-4;  // central-difference step in a ln-shape

// Model AVAR at each point and its derivative with respect to each ln-parameter (analytic in
// the amplitudes, whose AVAR is proportional to amplitude^2; central differences in the shapes).
// Each term's AVAR is evaluated once per point and serves both the sum and its amplitude column;
// the perturbed terms are built alone (this runs in every solver iteration).
void model_and_jacobian(const std::vector<FitPoint>& points, const ModelStructure& structure,
                        const std::vector<double>& log_parameters, Eigen::VectorXd* model_avar_values,
                        Eigen::MatrixXd* jacobian) {
  const NoiseModel model = model_from_log_parameters(structure, log_parameters);
  const int count = static_cast<int>(points.size());
  const size_t terms = model.terms.size();
  // Per point, the terms' AVARs in order, summed as model_avar sums them.
  Eigen::MatrixXd term_values(terms, count);
  *model_avar_values = Eigen::VectorXd(count);
  for (int k = 0; k < count; ++k) {
    double total = noise::white_rate_avar(model.output_quantization_density, points[k].tau_s);
    for (size_t i = 0; i < terms; ++i) {
      term_values(i, k) = term_avar(model.terms[i], points[k].tau_s);
      total += term_values(i, k);
    }
    (*model_avar_values)(k) = total;
  }
  if (jacobian == nullptr) return;
  *jacobian = Eigen::MatrixXd::Zero(count, parameter_count(structure));
  for (size_t i = 0; i < structure.slots.size(); ++i) {
    const int offset = parameter_offset(structure, static_cast<int>(i));
    const int parameters = slot_parameter_count(structure.slots[i]);
    for (int k = 0; k < count; ++k) (*jacobian)(k, offset) = 2.0 * term_values(i, k);
    for (int p = 1; p < parameters; ++p) {
      std::array<double, 3> up{}, down{};
      std::copy(log_parameters.begin() + offset, log_parameters.begin() + offset + parameters, up.begin());
      down = up;
      up[p] += kShapeStep;
      down[p] -= kShapeStep;
      const Term term_up = term_from_log_parameters(structure.slots[i], up.data());
      const Term term_down = term_from_log_parameters(structure.slots[i], down.data());
      for (int k = 0; k < count; ++k) {
        (*jacobian)(k, offset + p) =
            (term_avar(term_up, points[k].tau_s) - term_avar(term_down, points[k].tau_s)) / (2.0 * kShapeStep);
      }
    }
  }
}

// The whitened residuals L^-1 (z - ln nu(theta)) at the model's AVARs and, when asked (either
// may be null), their Jacobian from the model's. False where a model value is not positive and
// finite.
bool whitened_residuals(const std::vector<FitPoint>& points, const Eigen::VectorXd& model,
                        const Eigen::MatrixXd* model_jacobian, const MomentWeights& weights, Eigen::VectorXd* residuals,
                        Eigen::MatrixXd* jacobian) {
  if (!model.allFinite() || !(model.minCoeff() > 0.0)) return false;
  if (residuals != nullptr) {
    Eigen::VectorXd moments(points.size());
    for (size_t k = 0; k < points.size(); ++k) moments(k) = std::log(points[k].avar / model(k)) - weights.log_bias(k);
    *residuals = weights.whitening * moments;
  }
  if (model_jacobian != nullptr) *jacobian = -weights.whitening * (model.cwiseInverse().asDiagonal() * *model_jacobian);
  return true;
}

class MomentCost : public ceres::CostFunction {
 public:
  MomentCost(const std::vector<FitPoint>& points, const ModelStructure& structure, const MomentWeights& weights)
      : points_(points), structure_(structure), weights_(weights) {
    set_num_residuals(static_cast<int>(points.size()));
    mutable_parameter_block_sizes()->push_back(parameter_count(structure));
  }

  // Ceres evaluates every accepted point three times at the same bits: its projected line search's
  // trial (with the gradient, for the cubic interpolation), the candidate's cost, and the new
  // iterate's Jacobian. The last evaluation is remembered and served again: the same numbers.
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const int count = parameter_count(structure_);
    const bool want_jacobian = jacobians != nullptr && jacobians[0] != nullptr;
    const bool same_point = last_.evaluated && (!want_jacobian || last_.with_jacobian) &&
                            std::memcmp(last_.parameters.data(), parameters[0], count * sizeof(double)) == 0;
    if (!same_point) evaluate(parameters[0], want_jacobian);
    if (!(want_jacobian ? last_.jacobian_usable : last_.residuals_usable)) return false;
    Eigen::Map<Eigen::VectorXd>(residuals, last_.residuals.size()) = last_.residuals;
    if (want_jacobian) {
      Eigen::Map<RowMajorMatrix>(jacobians[0], last_.jacobian.rows(), last_.jacobian.cols()) = last_.jacobian;
    }
    return true;
  }

 private:
  using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  void evaluate(const double* parameters, bool with_jacobian) const {
    const int count = parameter_count(structure_);
    last_.parameters.assign(parameters, parameters + count);
    last_.evaluated = true;
    last_.with_jacobian = with_jacobian;
    last_.residuals_usable = last_.jacobian_usable = false;
    Eigen::VectorXd model;
    Eigen::MatrixXd jacobian;
    model_and_jacobian(points_, structure_, last_.parameters, &model, with_jacobian ? &jacobian : nullptr);
    Eigen::MatrixXd whitened_jacobian;
    if (!whitened_residuals(points_, model, with_jacobian ? &jacobian : nullptr, weights_, &last_.residuals,
                            &whitened_jacobian)) {
      return;
    }
    last_.residuals_usable = last_.residuals.allFinite();
    if (with_jacobian && last_.residuals_usable && whitened_jacobian.allFinite()) {
      last_.jacobian = whitened_jacobian;
      last_.jacobian_usable = true;
    }
  }

  struct Evaluation {
    std::vector<double> parameters;
    bool evaluated = false;
    bool with_jacobian = false;
    bool residuals_usable = false;
    bool jacobian_usable = false;
    Eigen::VectorXd residuals;
    RowMajorMatrix jacobian;
  };

  const std::vector<FitPoint>& points_;
  ModelStructure structure_;
  const MomentWeights& weights_;
  mutable Evaluation last_;  // Ceres runs one thread here (ceres_solver_options.h)
};

}  // namespace

std::vector<int> averaging_factors(const std::vector<FitPoint>& points) {
  std::vector<int> factors;
  for (const FitPoint& point : points) factors.push_back(point.averaging_factor);
  return factors;
}

std::vector<double> pooled_term_fractions(const std::vector<FitPoint>& points) {
  std::vector<double> fractions;
  for (const FitPoint& point : points) fractions.push_back(point.pooled_term_fraction);
  return fractions;
}

MomentWeights moment_weights(const std::vector<FitPoint>& points, const NoiseModel& model,
                             OavarCovariance& model_covariance, double discrepancy) {
  Eigen::VectorXd level(points.size());
  for (size_t k = 0; k < points.size(); ++k) level(k) = model_avar(model, points[k].tau_s);
  return moment_weights(level, model_covariance.covariance(model), discrepancy);
}

MomentWeights moment_weights(const Eigen::VectorXd& model_avars, const Eigen::MatrixXd& avar_covariance,
                             double discrepancy) {
  // Relative covariance: cov(nu_i, nu_j) / (nu_i nu_j) is the covariance of ln nu to first order;
  // it depends on the model's shape only, not on how far its level is from the data's. Its
  // diagonal gives each estimate's EDF, and the variance of ln nu is then trigamma(e / 2)
  // (chi_squared.h): the first order's 2 / e understates it 1.6-2.5 times at the few EDF of the
  // longest taus. The correlations stay the first order's.
  Eigen::MatrixXd covariance =
      model_avars.cwiseInverse().asDiagonal() * avar_covariance * model_avars.cwiseInverse().asDiagonal();
  const int count = static_cast<int>(model_avars.size());
  MomentWeights weights;
  weights.edf = Eigen::VectorXd(count);
  weights.log_bias = Eigen::VectorXd(count);
  Eigen::VectorXd log_scale(count);
  for (int k = 0; k < count; ++k) {
    weights.edf(k) = 2.0 / covariance(k, k);
    weights.log_bias(k) = mean_log_scaled_chi_squared(weights.edf(k));
    log_scale(k) = std::sqrt(variance_log_scaled_chi_squared(weights.edf(k)) / covariance(k, k));
  }
  covariance = log_scale.asDiagonal() * covariance * log_scale.asDiagonal();
  for (int k = 0; k < count; ++k) covariance(k, k) += discrepancy * discrepancy;
  Eigen::LLT<Eigen::MatrixXd> factor(covariance);
  if (factor.info() != Eigen::Success) {
    // The lag sums carry relative errors near 1e-5 (1e-3 for a resonance's truncated
    // oscillation), enough to tip the smallest eigenvalues of a strongly correlated matrix below
    // zero. Clip the correlation matrix's eigenvalues at 1e-6 of its size: the nearest usable
    // weights, which only give up directions the estimates do not tell apart anyway.
    const Eigen::VectorXd scale = covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
    if (!(scale.minCoeff() > 0.0)) {
      throw std::runtime_error("noise identification: the model gives an estimate no variance");
    }
    const Eigen::MatrixXd correlation =
        scale.cwiseInverse().asDiagonal() * covariance * scale.cwiseInverse().asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(correlation);
    const Eigen::VectorXd clipped = eigen.eigenvalues().cwiseMax(1e-6 * correlation.rows());
    const Eigen::MatrixXd repaired = eigen.eigenvectors() * clipped.asDiagonal() * eigen.eigenvectors().transpose();
    covariance = scale.asDiagonal() * repaired * scale.asDiagonal();
    factor.compute(covariance);
    if (factor.info() != Eigen::Success) {
      throw std::runtime_error("noise identification: the model's covariance of the AVAR estimates is singular");
    }
  }
  weights.discrepancy = discrepancy;
  const Eigen::MatrixXd lower = factor.matrixL();
  weights.whitening = lower.triangularView<Eigen::Lower>().solve(
      Eigen::MatrixXd::Identity(count, count));
  return weights;
}

void log_parameter_bounds(const ModelStructure& structure, const DataSpan& span, std::vector<double>* lower,
                          std::vector<double>* upper) {
  const double nyquist_hz = 1.0 / (2.0 * span.tau0_s);
  // Amplitudes: a box wide enough for any term that could matter (every kind's amplitude is
  // sqrt(AVAR) times a power of tau between 1 / tau0 and T), finite so that no step overflows.
  const double time_scale = std::max(span.record_length_s, 1.0 / span.tau0_s);
  const double log_amplitude_low = 0.5 * std::log(span.smallest_avar) - std::log(time_scale) - 30.0;
  const double log_amplitude_high = 0.5 * std::log(span.largest_avar) + std::log(time_scale) + std::log(10.0);
  lower->clear();
  upper->clear();
  for (const TermSlot& slot : structure.slots) {
    lower->push_back(log_amplitude_low);
    upper->push_back(log_amplitude_high);
    if (!slot.shape_free) continue;
    double low = 0.0, high = 0.0;
    switch (slot.kind) {
      case TermKind::kMarkov:
        // Faster than the shortest tau a Markov term is low-passed white noise: the front end's
        // job (a white rate term with its corner), not a Markov term's.
        low = span.tau_min_s;
        high = 2.0 * span.record_length_s;
        break;
      case TermKind::kSinusoid:
        low = std::min(kFewestLinePeriods / span.record_length_s, nyquist_hz);
        high = nyquist_hz;
        break;
      case TermKind::kBiasInstability:
        low = 1.0 / span.record_length_s;
        high = nyquist_hz;
        break;
      case TermKind::kResonance:
        // A mode of the sensor or its mount, tens of samples per period at most; slower wander
        // is the Markov terms' and narrow lines are sinusoids.
        low = 0.1 * nyquist_hz;
        high = nyquist_hz;
        break;
      case TermKind::kWhiteRate:
        // An anti-alias filter sits near the Nyquist frequency; a corner far inside the band is
        // a Markov process in the signal, which the Markov term describes.
        low = 0.1 / span.tau0_s;
        high = 5.0 / span.tau0_s;
        break;
      case TermKind::kHighPassWhite:
        // Slower than the record, the high-pass is plain white noise; faster than the Nyquist
        // frequency, it has removed all of it.
        low = 1.0 / span.record_length_s;
        high = nyquist_hz;
        break;
      case TermKind::kZeroDcGaussian:  // beta [s^2]: the PSD's peak at 1 / sqrt(beta) inside the band
        low = span.tau0_s * span.tau0_s;
        high = span.record_length_s * span.record_length_s;
        break;
      default:  // zero-DC family beta [s]
        low = span.tau0_s;
        high = span.record_length_s;
        break;
    }
    lower->push_back(std::log(low));
    upper->push_back(std::log(high));
    if (slot.kind == TermKind::kResonance) {  // width / f_n: from a sharp peak to near-critical damping
      lower->push_back(std::log(kSmallestResonanceRelativeWidth));
      upper->push_back(std::log(1.9));
    }
  }
}

namespace {

// Ends a solve at the first iterate whose cost lies below a level (Ceres accepts only steps that
// lower the cost, so the minimum it would reach lies below too).
class CostBelow : public ceres::IterationCallback {
 public:
  explicit CostBelow(double level) : level_(level) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    return summary.cost < level_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  double level_;
};

// Ends a solve as soon as the computation is cancelled (cancellation.h); the caller then throws.
class AbortWhenCancelled : public ceres::IterationCallback {
 public:
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return cancellation_requested() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }
};

}  // namespace

SolveOutcome solve_model(const std::vector<FitPoint>& points, const ModelStructure& structure,
                         const std::vector<double>& start, const DataSpan& span, const MomentWeights& weights,
                         const std::vector<int>& held_fixed, double stop_below_cost) {
  std::vector<double> lower, upper;
  log_parameter_bounds(structure, span, &lower, &upper);
  std::vector<double> parameters = start;
  for (size_t i = 0; i < parameters.size(); ++i) parameters[i] = std::min(std::max(parameters[i], lower[i]), upper[i]);
  SolveOutcome outcome;
  if (held_fixed.size() == parameters.size()) {
    outcome.log_parameters = parameters;
    outcome.cost = model_cost(points, structure, parameters, weights);
    outcome.usable = std::isfinite(outcome.cost);
    return outcome;
  }
  ceres::Problem problem;
  problem.AddResidualBlock(new MomentCost(points, structure, weights), nullptr, parameters.data());
  for (size_t i = 0; i < parameters.size(); ++i) {
    if (std::isfinite(lower[i])) problem.SetParameterLowerBound(parameters.data(), static_cast<int>(i), lower[i]);
    if (std::isfinite(upper[i])) problem.SetParameterUpperBound(parameters.data(), static_cast<int>(i), upper[i]);
  }
  if (!held_fixed.empty()) {
    problem.SetManifold(parameters.data(), new ceres::SubsetManifold(static_cast<int>(parameters.size()), held_fixed));
  }
  ceres::Solver::Options options = small_fit_solver_options({100, 1e-10, 1e-12, 1e-10});
  CostBelow stop(stop_below_cost);
  if (std::isfinite(stop_below_cost)) options.callbacks.push_back(&stop);
  AbortWhenCancelled cancel;
  options.callbacks.push_back(&cancel);
  throw_if_cancelled();
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  throw_if_cancelled();
  outcome.log_parameters = parameters;
  outcome.cost = summary.final_cost;
  outcome.usable = summary.IsSolutionUsable() && std::isfinite(summary.final_cost);
  return outcome;
}

double moment_distance(const std::vector<FitPoint>& points, const Eigen::VectorXd& model_values,
                       const MomentWeights& weights) {
  Eigen::VectorXd residuals;
  if (!whitened_residuals(points, model_values, nullptr, weights, &residuals, nullptr)) {
    return std::numeric_limits<double>::infinity();
  }
  return residuals.squaredNorm();
}

double model_cost(const std::vector<FitPoint>& points, const ModelStructure& structure,
                  const std::vector<double>& log_parameters, const MomentWeights& weights) {
  Eigen::VectorXd model;
  model_and_jacobian(points, structure, log_parameters, &model, nullptr);
  return 0.5 * moment_distance(points, model, weights);
}

Eigen::MatrixXd log_parameter_covariance(const std::vector<FitPoint>& points, const ModelStructure& structure,
                                         const std::vector<double>& log_parameters, const MomentWeights& weights) {
  Eigen::VectorXd model;
  Eigen::MatrixXd jacobian;
  model_and_jacobian(points, structure, log_parameters, &model, &jacobian);
  Eigen::MatrixXd whitened;
  if (!whitened_residuals(points, model, &jacobian, weights, nullptr, &whitened)) {
    throw std::runtime_error("noise identification: the model has no positive AVAR at the estimate");
  }
  const Eigen::MatrixXd information = whitened.transpose() * whitened;
  return information.completeOrthogonalDecomposition().pseudoInverse();
}

}  // namespace identify
}  // namespace imu_lab
