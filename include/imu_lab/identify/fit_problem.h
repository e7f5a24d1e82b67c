// One fit of a fixed model structure by the generalized method of wavelet moments (Guerrier,
// Skaloud, Stebler and Victoria-Feser, JASA 2013; doc/models.md), on logarithms: the moments are
// z = ln nu - E ln(chi2_e / e) (each measured AVAR's log, unbiased at its EDF e), matched to
// ln nu(theta) in the distance
//   J(theta) = (z - ln nu(theta))' R^-1 (z - ln nu(theta)),
// where R is the covariance of the logs of the estimates under a previous model (avar_covariance.h
// gives their covariance, which carries the EDFs and the correlations across taus; each log's
// variance is trigamma(e / 2), chi_squared.h), plus a relative discrepancy variance for what no
// model of this family describes (a real front end that is not exactly first order, for
// instance). R depends on the model's shape only, never on how far its level is from the data's.
// With R fixed the difference of J between nested models is a chi-squared statistic (the GMM
// distance test). Parameters are logarithms; shapes are bounded to what the data can express.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "imu_lab/identify/avar_covariance.h"
#include "imu_lab/identify/chi_squared.h"
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

// R^-1/2 for the fit points: residuals r = L^-1 (z - ln nu(theta)) with R = L L'.
struct MomentWeights {
  Eigen::MatrixXd whitening;  // L^-1
  Eigen::VectorXd log_bias;   // E ln(chi2_e / e) at each point's EDF under the weighing model
  double discrepancy = 0.0;   // relative standard deviation added to every point
  Eigen::VectorXd edf;        // 2 / relative variance of each estimate under the weighing model
};

// The weights under `model` (its relative covariance of the estimates, from `covariance`, which
// holds the fit points' averaging factors, plus discrepancy^2 on the diagonal). A covariance
// that rounding made indefinite has its correlation eigenvalues clipped. Throws
// std::runtime_error if even that fails.
MomentWeights moment_weights(const std::vector<FitPoint>& points, const NoiseModel& model, OavarCovariance& covariance,
                             double discrepancy);
// The same from the model's AVAR at each point and the covariance of the estimates under it.
MomentWeights moment_weights(const Eigen::VectorXd& model_avars, const Eigen::MatrixXd& avar_covariance,
                             double discrepancy);

// The averaging factors of the points, in order (what an OavarCovariance for them needs).
std::vector<int> averaging_factors(const std::vector<FitPoint>& points);
// Their pooled term fractions (OavarCovariance::set_pooled_term_fractions).
std::vector<double> pooled_term_fractions(const std::vector<FitPoint>& points);

struct SolveOutcome {
  std::vector<double> log_parameters;
  double cost = 0.0;  // J / 2
  bool usable = false;
};

// A resonance narrower than this (relative to f_n) is a line: a sinusoid describes it.
constexpr double kSmallestResonanceRelativeWidth = 0.02;

// A line holds at least this many periods in the record. Its AVAR peaks at tau = 0.371 / f and
// falls after it; with fewer periods that fall lies at taus of a few degrees of freedom, where a
// slow line can carry the rise of a random walk or ramp (doc/identification.md, "Selection").
constexpr double kFewestLinePeriods = 10.0;

// Bounds of each ln-parameter: amplitudes in a wide finite box (see the source); Markov T_c in
// [tau_min, 2 T]; sinusoid frequencies in [kFewestLinePeriods / T, 1 / (2 tau0)] and bias
// cutoff frequencies in [1 / T, 1 / (2 tau0)]; resonance
// f_n in [0.05 / tau0, 1 / (2 tau0)] and width / f_n in [0.02, 1.9]; a white rate's front-end
// corner in [0.1 / tau0, 5 / tau0]; zero-DC beta in [tau0, T].
void log_parameter_bounds(const ModelStructure& structure, const DataSpan& span, std::vector<double>* lower,
                          std::vector<double>* upper);

// Minimises J from `start` (clamped into the bounds); parameters listed in held_fixed keep their
// start values (profiles). A profile that only asks whether the minimum lies below a cost can
// give it as stop_below_cost: the solver stops at the first iterate under it (its steps only
// lower the cost, so the full minimum would lie below too) and returns that iterate.
SolveOutcome solve_model(const std::vector<FitPoint>& points, const ModelStructure& structure,
                         const std::vector<double>& start, const DataSpan& span, const MomentWeights& weights,
                         const std::vector<int>& held_fixed = {},
                         double stop_below_cost = -std::numeric_limits<double>::infinity());

// J at the model's AVAR at each point; infinity where one is not positive and finite.
double moment_distance(const std::vector<FitPoint>& points, const Eigen::VectorXd& model_values,
                       const MomentWeights& weights);

// J / 2 at given parameters.
double model_cost(const std::vector<FitPoint>& points, const ModelStructure& structure,
                  const std::vector<double>& log_parameters, const MomentWeights& weights);

// Covariance of the ln-parameters, (G' G)^-1 with G the whitened Jacobian (the GMM sandwich
// collapses to this with the optimal weights); pseudo-inverse when rank deficient.
Eigen::MatrixXd log_parameter_covariance(const std::vector<FitPoint>& points, const ModelStructure& structure,
                                         const std::vector<double>& log_parameters, const MomentWeights& weights);

}  // namespace identify
}  // namespace imu_lab
