// The doubt between two descriptions of one spectral peak. A peak the selection took for a line
// (sinusoid) is often described almost as well by a narrow resonance, and the other way round
// (doc/identification.md, "Emulated coverage": a 20 Hz mode 6 Hz wide beside a 40 Hz front end);
// the terms beside it, the white noise and its front-end corner above all, take different values
// under the two descriptions, and the moment covariance of the selected structure does not carry
// that. Each alternative (the peak's slot swapped for the other kind, fitted under the selected
// model's weights) is weighed against the selected structure by Akaike's criterion on the GMM
// distance, J + 2 x parameters (Andrews, Econometrica 1999); every parameter the structures share
// then gets as its log-variance its mean squared distance from the reported (selected) value over
// the structures (Buckland, Burnham and Augustin, Biometrics 1997):
//   w_sel var_sel + sum_a w_a (var_a + (ln theta_a - ln theta_sel)^2).
// The reported values stay the selected model's, so the drawn total is still the fitted one.
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
  std::string replaced;     // term name in the selected model, e.g. "sinusoid_1"
  std::string replacement;  // kind name of the term put in its place, e.g. "resonance"
  double peak_frequency_hz = 0.0;  // the replaced term's frequency
  double distance_change = 0.0;    // J(alternative) - J(selected), same weights
  int parameter_change = 0;        // parameters(alternative) - parameters(selected)
  double weight = 0.0;             // Akaike weight among the selected structure and the alternatives
};

// Fits the alternative of every line and resonance of the selected structure (only kinds
// `options` allows) and widens `log_covariance` (of `log_parameters`) by the spread between the
// structures as above. Returns the alternatives that could be fitted, in slot order.
std::vector<StructureAlternative> weigh_peak_alternatives(const std::vector<FitPoint>& points, const DataSpan& span,
                                                          const FitOptions& options, const ModelStructure& structure,
                                                          const std::vector<double>& log_parameters, double cost,
                                                          const MomentWeights& weights,
                                                          Eigen::MatrixXd* log_covariance);

}  // namespace identify
}  // namespace imu_lab
