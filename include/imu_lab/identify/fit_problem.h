// One fit of a fixed model structure by the generalized method of wavelet moments (Guerrier,
// Skaloud, Stebler and Victoria-Feser, JASA 2013; doc/models.md): the measured AVARs nu are
// matched to the model's nu(theta) in the distance
//   J(theta) = (nu - nu(theta))' Omega^-1 (nu - nu(theta)),
// where Omega is the covariance of the estimates (avar_covariance.h) at a previous model, plus a
// relative discrepancy variance for what no model of this family describes (a real front end
// that is not exactly first order, for instance). With Omega fixed, J is a plain weighted least
// squares: nu(theta) enters linearly in the residual, so the estimator is unbiased, and the
// difference of J between nested models is a chi-squared statistic (the GMM distance test).
// Parameters are logarithms; shapes are bounded to what the data can express.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "imu_lab/identify/avar_covariance.h"
#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/model_structure.h"

namespace imu_lab {
namespace identify {

// What the record can resolve: shape parameters are kept where they change the curve.
struct DataSpan {
  double tau0_s = 0.0;
  double record_length_s = 0.0;
  long long sample_count = 0;  // samples behind the curve
  double tau_min_s = 0.0;      // smallest fitted tau
  double tau_max_s = 0.0;      // largest fitted tau
  double smallest_avar = 0.0;  // of the fitted points
  double largest_avar = 0.0;
};

// Omega^-1/2 for the fit points: residuals r = L^-1 (nu - nu(theta)) with Omega = L L'.
struct MomentWeights {
  Eigen::MatrixXd whitening;  // L^-1
  double discrepancy = 0.0;   // relative standard deviation added to every point
};

// The weights under `model` (its covariance of the estimates, from `covariance`, which holds the
// fit points' averaging factors, plus (discrepancy * nu_model)^2 on the diagonal). If the
// covariance is numerically singular a ridge of 1e-9 of its diagonal is added. Throws
// std::runtime_error if even that fails.
MomentWeights moment_weights(const std::vector<FitPoint>& points, const NoiseModel& model,
                             OavarCovariance& covariance, double discrepancy);

// The averaging factors of the points, in order (what an OavarCovariance for them needs).
std::vector<int> averaging_factors(const std::vector<FitPoint>& points);

struct SolveOutcome {
  std::vector<double> log_parameters;
  double cost = 0.0;  // J / 2
  bool usable = false;
};

// A resonance narrower than this (relative to f_n) is a line: a sinusoid describes it.
constexpr double kSmallestResonanceRelativeWidth = 0.02;

// Bounds of each ln-parameter: amplitudes in a wide finite box (see the source); Markov T_c in
// [tau_min / 4, 2 T]; sinusoid and bias cutoff frequencies in [1 / T, 1 / (2 tau0)]; resonance
// f_n in [0.05 / tau0, 1 / (2 tau0)] and width / f_n in [0.02, 1.9]; a white rate's front-end
// corner in [0.01 / tau0, 5 / tau0]; zero-DC beta in [tau0, T].
void log_parameter_bounds(const ModelStructure& structure, const DataSpan& span,
                          std::vector<double>* lower, std::vector<double>* upper);

// Minimises J from `start` (clamped into the bounds); parameters listed in held_fixed keep their
// start values (profiles).
SolveOutcome solve_model(const std::vector<FitPoint>& points, const ModelStructure& structure,
                         const std::vector<double>& start, const DataSpan& span,
                         const MomentWeights& weights, const std::vector<int>& held_fixed = {});

// J / 2 at given parameters.
double model_cost(const std::vector<FitPoint>& points, const ModelStructure& structure,
                  const std::vector<double>& log_parameters, const MomentWeights& weights);

// Covariance of the ln-parameters, (G' G)^-1 with G the whitened Jacobian (the GMM sandwich
// collapses to this with the optimal weights); pseudo-inverse when rank deficient.
Eigen::MatrixXd log_parameter_covariance(const std::vector<FitPoint>& points, const ModelStructure& structure,
                                         const std::vector<double>& log_parameters, const MomentWeights& weights);

}  // namespace identify
}  // namespace imu_lab
