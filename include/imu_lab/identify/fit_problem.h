// One maximum-likelihood fit of a fixed model structure with Ceres: residuals are the signed
// deviance roots of the octave points (avar_likelihood.h), parameters their logarithms, a Huber
// loss limits what a few bad points can do. Shapes are bounded to what the data can express.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/model_structure.h"

namespace imu_lab {
namespace identify {

// What the record can resolve: shape parameters are kept where they change the curve.
struct DataSpan {
  double tau0_s = 0.0;
  double record_length_s = 0.0;
  double tau_min_s = 0.0;  // smallest fitted tau
  double tau_max_s = 0.0;  // largest fitted tau
};

struct SolverSettings {
  // Huber threshold on the deviance residual (a standard-normal-like quantity); 0 = no loss.
  double robust_loss_scale = 3.0;
  int max_iterations = 100;
};

struct SolveOutcome {
  std::vector<double> log_parameters;
  double cost = 0.0;  // 1/2 sum rho(r^2): the robustified negative log-likelihood + const
  bool usable = false;
};

// Bounds of each ln-parameter: amplitudes free, Markov T_c in [tau_min / 4, 2 T], sinusoid and
// bias cutoff frequencies in [1 / T, 1 / (2 tau0)], zero-DC beta in [tau0, T].
void log_parameter_bounds(const ModelStructure& structure, const DataSpan& span,
                          std::vector<double>* lower, std::vector<double>* upper);

// Solves from `start` (clamped into the bounds); parameters listed in held_fixed keep their
// start values (profile likelihood).
SolveOutcome solve_model(const std::vector<FitPoint>& points, const ModelStructure& structure,
                         const std::vector<double>& start, const DataSpan& span,
                         const SolverSettings& settings,
                         const std::vector<int>& held_fixed = {});

// The robustified cost at given parameters, as solve_model() reports it.
double model_cost(const std::vector<FitPoint>& points, const ModelStructure& structure,
                  const std::vector<double>& log_parameters, const SolverSettings& settings);

// Ceres' covariance of the ln-parameters at `log_parameters` (inverse Gauss-Newton Hessian of
// the likelihood on the octave points, pseudo-inverse when rank deficient). False if Ceres fails.
bool log_parameter_covariance(const std::vector<FitPoint>& points, const ModelStructure& structure,
                              const std::vector<double>& log_parameters,
                              const SolverSettings& settings, Eigen::MatrixXd* covariance);

}  // namespace identify
}  // namespace imu_lab
