// What the identification returns: each term with its status, value, uncertainty (and where the
// uncertainty came from), bounds for what the data cannot constrain, the fit's quality, the
// check of the fitted curve against the measured one's confidence band, the graphical readings
// beside it and the warnings.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "imu_lab/identify/fit_finding.h"
#include "imu_lab/identify/fit_options.h"
#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/fit_problem.h"
#include "imu_lab/identify/graphical_readings.h"
#include "imu_lab/identify/model_selection.h"
#include "imu_lab/identify/model_structure.h"
#include "imu_lab/identify/structure_doubt.h"

namespace imu_lab {
namespace identify {

// present: in the model, removal worsens the fit significantly and its sigma is useful.
// unconstrained: in the model but its relative sigma exceeds options.unconstrained_relative_sigma;
//   report the upper bound, not the value. absent: not in the model; upper bound only.
enum class TermStatus { kPresent, kUnconstrained, kAbsent };
std::string term_status_name(TermStatus status);  // "present", "unconstrained", "absent"

// moment_covariance: (G' Omega^-1 G)^-1 of the GMM fit, with Omega the model's own covariance of
//   the AVAR estimates across taus (fast; the default).
// bootstrap: spread of refits of records simulated from the fitted model (bootstrap.h).
enum class SigmaSource { kNone, kMomentCovariance, kBootstrap };
std::string sigma_source_name(SigmaSource source);  // "none", "moment_covariance", "bootstrap"

struct ParameterEstimate {
  static constexpr double kNotAvailable = std::numeric_limits<double>::quiet_NaN();
  double value = kNotAvailable;        // SI; NaN when absent
  double sigma = kNotAvailable;        // SI, one sigma (value * log_sigma); NaN when not estimated
  double log_sigma = kNotAvailable;    // one sigma of ln(value): the fit works on logarithms
  double upper_bound = kNotAvailable;  // SI, one-sided profile bound; NaN if none
  // SI, one-sided profile bound at 68.27 % (profile_likelihood.h): [0, it] is the term's 68.3 %
  // interval when it is reported absent or unconstrained; NaN if none.
  double upper_bound_one_sigma = kNotAvailable;
  // The structures weighed for this parameter (structure_doubt.h), the selected one first; empty
  // when no alternative was weighed (or the sigma is the bootstrap's).
  std::vector<LogNormalComponent> structure_mixture;
  // The interval of probability erf(z / sqrt 2): value * exp(+-z log_sigma), symmetric in
  // ln(value) and so asymmetric in value; with a structure mixture, its quantiles instead (the
  // model-averaged tail area interval), which may be asymmetric in ln(value) too.
  double interval_low(double z) const;
  double interval_high(double z) const;
};

struct TermEstimate {
  std::string name;  // "white_rate", "markov_1", ...
  TermKind kind = TermKind::kWhiteRate;
  TermStatus status = TermStatus::kAbsent;
  ParameterEstimate amplitude;
  ParameterEstimate shape;  // Markov T_c, sinusoid f, bias cutoff f0, front-end corner, f_n
  ParameterEstimate width;  // resonance -3 dB width
  bool shape_fitted = false;
  // The rise of the GMM distance on removing a model term, or its fall on adding an absent one,
  // and the threshold it was compared with.
  double selection_statistic = std::numeric_limits<double>::quiet_NaN();
  double selection_threshold = std::numeric_limits<double>::quiet_NaN();
  bool borderline = false;  // the statistic is within a factor 2 of its threshold
  SigmaSource sigma_source = SigmaSource::kNone;
};

struct FitQuality {
  double distance = 0.0;  // GMM distance J at the estimate (chi2 with points - parameters dof)
  int points = 0;
  int parameters = 0;
  int degrees_of_freedom = 0;
  double distance_per_dof = 0.0;
  double p_value = 0.0;  // P(chi2(dof) > distance)
  // Relative spread added to every point's variance because the model does not describe the
  // curve to the precision of the estimates (0: it does).
  double discrepancy = 0.0;
};

// The fitted total against the measured deviation at one tau of the curve: the 95 % chi-squared
// band at the fitted model's EDF, never narrower than +-1 % in deviation.
struct BandPoint {
  double tau_s = 0.0;
  double measured_deviation = 0.0;
  double fitted_deviation = 0.0;
  double edf = 0.0;  // of the estimate under the fitted model
  double lower = 0.0;
  double upper = 0.0;
  bool inside() const { return fitted_deviation >= lower && fitted_deviation <= upper; }
};

// The band's confidence and its narrowest half-width in deviation.
constexpr double kBandConfidence = 0.95;
constexpr double kBandMinimumHalfWidth = 0.01;

// The band around a measured deviation estimated with `edf` degrees of freedom.
struct BandLimits {
  double lower = 0.0;
  double upper = 0.0;
};
BandLimits band_limits(double measured_deviation, double edf);

struct FitResult {
  NoiseModel model;  // the terms in the model (present and unconstrained), canonical order
  ModelStructure structure;
  std::vector<double> log_parameters;
  Eigen::MatrixXd log_covariance;   // of log_parameters
  std::vector<TermEstimate> terms;  // model terms in order, then absent candidate terms
  std::vector<FitPoint> points;     // the points the estimator used
  std::vector<BandPoint> band;      // every point of the curve
  FitQuality quality;
  GraphicalReadings graphical;
  std::vector<std::string> warnings;  // the findings' sentences
  std::vector<FitFinding> findings;
  std::vector<SelectionStep> selection_steps;
  // The other description of each line or resonance, and its weight in the sigmas
  // (structure_doubt.h).
  std::vector<StructureAlternative> structure_alternatives;
  double tau0_s = 0.0;
  double record_length_s = 0.0;
  DataSpan span;
  MomentWeights weights;  // the final fit's (profiles and the bootstrap's refits use them)
  FitOptions options;

  // The term with this name, or nullptr.
  const TermEstimate* find(const std::string& name) const;
  TermEstimate* find(const std::string& name);
};

// The five IEEE Std 952 terms first, N (white rate), B, K, Q, R, then the others in model order:
// the order of every report.
std::vector<const TermEstimate*> terms_in_report_order(const FitResult& fit);

}  // namespace identify
}  // namespace imu_lab
