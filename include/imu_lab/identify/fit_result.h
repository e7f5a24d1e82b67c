// What the identification returns: each term with its status, value, uncertainty (and where the
// uncertainty came from), bounds for what the data cannot constrain, the fit's quality, the
// graphical readings beside it and the warnings that compare the two.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "imu_lab/identify/fit_options.h"
#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/graphical_readings.h"
#include "imu_lab/identify/model_selection.h"
#include "imu_lab/identify/model_structure.h"

namespace imu_lab {
namespace identify {

// present: in the model, removal worsens the fit significantly and its sigma is useful.
// unconstrained: in the model but its relative sigma exceeds options.unconstrained_relative_sigma;
//   report the upper bound, not the value. absent: not in the model; upper bound only.
enum class TermStatus { kPresent, kUnconstrained, kAbsent };
std::string term_status_name(TermStatus status);  // "present", "unconstrained", "absent"

// ceres_covariance: inverse Hessian of the likelihood on octave points (fast; ignores the
//   remaining correlation between octave points, so optimistic where random walk dominates).
// bootstrap: spread of refits of records simulated from the fitted model (bootstrap.h).
enum class SigmaSource { kNone, kCeresCovariance, kBootstrap };
std::string sigma_source_name(SigmaSource source);  // "none", "ceres_covariance", "bootstrap"

struct ParameterEstimate {
  static constexpr double kNotAvailable = std::numeric_limits<double>::quiet_NaN();
  double value = kNotAvailable;        // SI; NaN when absent
  double sigma = kNotAvailable;        // SI, one sigma; NaN when not estimated
  double upper_bound = kNotAvailable;  // SI, one-sided profile-likelihood bound; NaN if none
};

struct TermEstimate {
  std::string name;  // "white_rate", "markov_1", ...
  TermKind kind = TermKind::kWhiteRate;
  TermStatus status = TermStatus::kAbsent;
  ParameterEstimate amplitude;
  ParameterEstimate shape;  // Markov T_c, sinusoid f, bias cutoff f0; value only if fixed
  bool shape_fitted = false;
  double removal_lr_statistic = std::numeric_limits<double>::quiet_NaN();
  SigmaSource sigma_source = SigmaSource::kNone;
};

struct FitQuality {
  double deviance = 0.0;  // sum over octave points of edf (u - 1 - ln u), no robust loss
  int points = 0;
  int parameters = 0;
  int degrees_of_freedom = 0;
  double deviance_per_dof = 0.0;
  double p_value = 0.0;  // P(chi2(dof) > deviance)
};

struct FitResult {
  NoiseModel model;  // the terms in the model (present and unconstrained), canonical order
  ModelStructure structure;
  std::vector<double> log_parameters;
  Eigen::MatrixXd log_covariance;  // Ceres covariance of log_parameters
  std::vector<TermEstimate> terms;  // model terms in order, then absent candidate terms
  std::vector<FitPoint> points;     // the octave points the likelihood used
  FitQuality quality;
  GraphicalReadings graphical;
  std::vector<std::string> warnings;
  std::vector<SelectionStep> selection_steps;
  double tau0_s = 0.0;
  double record_length_s = 0.0;
  FitOptions options;

  // The term with this name, or nullptr.
  const TermEstimate* find(const std::string& name) const;
  TermEstimate* find(const std::string& name);
};

}  // namespace identify
}  // namespace imu_lab
