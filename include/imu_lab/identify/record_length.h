// How long a record must be: the information the estimator (fit_problem.h) would have for a
// record of another length, from the model itself: its relative covariance of the AVAR
// estimates (avar_covariance.h) at the fit's spacing of averaging factors up to what that record
// can evaluate. (G' R^-1 G)^-1 is then the covariance of the ln-parameters, so sqrt(diagonal) is
// each parameter's relative sigma.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "imu_lab/identify/fit_result.h"
#include "imu_lab/identify/model_structure.h"

namespace imu_lab {
namespace identify {

// Covariance of the ln-parameters of `structure` at `log_parameters` for a record of
// record_length_s sampled every tau0_s. Empty if singular.
Eigen::MatrixXd predicted_log_covariance(const ModelStructure& structure, const std::vector<double>& log_parameters,
                                         double tau0_s, double record_length_s);

// Relative sigma of parameter `parameter_index` (an index into the ln-parameters) predicted for a
// record of record_length_s; infinity if the information is singular.
double predicted_relative_sigma(const ModelStructure& structure, const std::vector<double>& log_parameters,
                                int parameter_index, double tau0_s, double record_length_s);

// Shortest record (s) for which predicted_relative_sigma() <= target, searched from 100 samples
// to 1e4 times current_length_s; infinity if even that is not enough.
double required_record_length_s(const ModelStructure& structure, const std::vector<double>& log_parameters,
                                int parameter_index, double tau0_s, double current_length_s,
                                double target_relative_sigma);

// The record length a fit says it needs for `term_name`'s amplitude to reach the target
// relative sigma. The predicted length is scaled by (reported sigma / predicted sigma)^2 at the
// current length, so a sigma that carries more than the model's own noise (a discrepancy, a
// bootstrap's non-linearity) carries its realism over; sigma ~ 1 / sqrt(T) is assumed for that
// ratio. Infinity if the term is not in the model or cannot reach the target. Throws
// std::invalid_argument for an unknown term.
double required_record_length_s(const FitResult& fit, const std::string& term_name, double target_relative_sigma);

}  // namespace identify
}  // namespace imu_lab
