// The doubt between structures that describe the curve almost equally well. A peak the selection
// took for a line (sinusoid) is often described almost as well by a narrow resonance, and the
// other way round (doc/identification.md, "Emulated coverage": a 20 Hz mode 6 Hz wide beside a
// 40 Hz front end); a term left out just below its threshold (B beside K) would, if added, move
// the terms that took its share; so would a slow Markov hump left out on a floor of bias
// instability. The moment covariance of the selected structure carries none of these.
// Each alternative (a peak's slot swapped for the other kind, or one left-out term added), fitted
// under the selected model's weights, is weighed against the selected structure by Akaike's
// criterion on the GMM distance, J + 2 x parameters (Andrews, Econometrica 1999); every parameter
// the structures share then gets as its log-variance its mean squared distance from the reported
// (selected) value over the structures (the mean-square form of Burnham and Anderson, Model
// Selection and Multimodel Inference, 2nd ed. 2002, section 6.3; Buckland, Burnham and Augustin,
// Biometrics 1997, average the root):
//   w_sel var_sel + sum_a w_a (var_a + (ln theta_a - ln theta_sel)^2),
// var_a the alternative's own for a swapped peak and an added Markov term (unless that term is
// left loose), the selected one's for an added one-parameter term (which may have gone to a
// negligible amplitude, where its own covariance is singular). That is what `sigma` reports.
// The reported values stay the selected model's, so the drawn total is still the fitted one. The
// intervals are the mixture's own quantiles, the model-averaged tail area limits of Turek and
// Fletcher (Computational Statistics & Data Analysis 2012): an alternative that moves a
// parameter one way widens its interval on that side only.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "imu_lab/identify/fit_options.h"
#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/fit_problem.h"
#include "imu_lab/identify/model_structure.h"

namespace imu_lab {
namespace identify {

struct StructureAlternative {
  std::string replaced;     // term name in the selected model, e.g. "sinusoid_1"; empty for an addition
  std::string replacement;  // kind name of the term put in its place or added, e.g. "resonance"
  double peak_frequency_hz = 0.0;  // the replaced term's frequency; NaN for an addition
  double distance_change = 0.0;    // J(alternative) - J(selected), same weights
  int parameter_change = 0;        // parameters(alternative) - parameters(selected)
  double weight = 0.0;             // Akaike weight among the selected structure and the alternatives
  // Per selected log-parameter: ln(theta_alternative / theta_selected), 0 where not shared.
  std::vector<double> log_parameter_offsets;
  // The alternative's own covariance of the selected log-parameters about its values (an
  // addition, and the replaced slot: the selected structure's; the replaced slot uncorrelated
  // with the rest).
  Eigen::MatrixXd log_covariance;
};

// One structure's share in the uncertainty of a parameter's logarithm: its weight, its value's
// offset from the reported (selected) one, and its own sigma.
struct LogNormalComponent {
  double weight = 1.0;
  double log_offset = 0.0;
  double log_sigma = 0.0;
};

// For the combination c' ln(theta) of the selected log-parameters: the selected structure (the
// weight the alternatives leave, offset 0, its sigma from `selected_log_covariance`), then each
// alternative with its weight, offset and own sigma.
std::vector<LogNormalComponent> structure_mixture(const std::vector<StructureAlternative>& alternatives,
                                                  const Eigen::MatrixXd& selected_log_covariance,
                                                  const Eigen::VectorXd& combination);

// The `probability` quantile of the weighted mixture of normals: a model-averaged tail area
// limit of ln(value / reported value). Components of zero sigma are steps at their offset.
double mixture_log_quantile(const std::vector<LogNormalComponent>& components, double probability);

// A term the selection left out, fitted freely beside the selected ones: `structure` is the
// selected one with the term's slot appended, `outcome` the fit.
struct TermAddition {
  TermKind kind = TermKind::kWhiteRate;
  ModelStructure structure;
  SolveOutcome outcome;
};

// Fits the other description of every line and resonance of the selected structure (only kinds
// `options` allows), weighs them and the `additions` (their fits usable) against it, and widens
// `log_covariance` (of `log_parameters`) by the spread between the structures as above. Returns
// the alternatives weighed, the swapped peaks in slot order, then the additions.
std::vector<StructureAlternative> weigh_structure_alternatives(const std::vector<FitPoint>& points,
                                                               const DataSpan& span, const FitOptions& options,
                                                               const ModelStructure& structure,
                                                               const std::vector<double>& log_parameters, double cost,
                                                               const MomentWeights& weights,
                                                               const std::vector<TermAddition>& additions,
                                                               Eigen::MatrixXd* log_covariance);

struct SelectedModel;
class OavarCovariance;

// Each line of `selected` refitted as a resonance (from the starts the doubt uses) under weights
// at `discrepancy`, kept where J falls by more than one parameter's chi2 quantile at the
// selection's significance (the line is a resonance of zero width, so the two are nested). The
// selection under a 1 % spread cannot tell a mode from a line where only the shortest taus see
// the width; the estimates' own precision often can. True when a line was swapped.
bool swap_lines_for_modes(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                          OavarCovariance& covariance, double discrepancy, SelectedModel* selected);

// Each resonance of `selected` refitted as a line (under its own weights), taken where the line
// fits at least as well: a structure with a parameter more and a higher J is dominated, whatever
// the criterion. A line is not a resonance's limit here (the width has a floor, and the two AVARs
// differ), so the selection, which adds a mode or a line by its own threshold, can end with a
// mode the line describes better (doc/identification.md, "Selection").
void swap_dominated_modes_for_lines(const std::vector<FitPoint>& points, const DataSpan& span,
                                    const FitOptions& options, OavarCovariance& covariance, double discrepancy,
                                    SelectedModel* selected);

}  // namespace identify
}  // namespace imu_lab
