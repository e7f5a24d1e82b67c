// How long a record must be: the Fisher information of the octave-point likelihood for a record
// of a given length, built from the model itself (each point's EDF from Greenhall's algorithm
// for the noise type that dominates the model at that tau). Its inverse is the Cramér-Rao
// covariance of the ln-parameters, so sqrt(diagonal) is the relative sigma of each parameter.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "imu_lab/identify/fit_result.h"
#include "imu_lab/identify/model_structure.h"

namespace imu_lab {
namespace identify {

// Frequency power-law exponent alpha (2 white PM ... -2 RW FM) of the term that dominates the
// model's AVAR at tau; used to pick the EDF of a hypothetical point.
int dominant_noise_alpha(const NoiseModel& model, double tau_s);

// Cramér-Rao covariance of the ln-parameters of `structure` at `log_parameters` for a record of
// record_length_s sampled every tau0_s, fitted on octave points. Empty if singular.
Eigen::MatrixXd predicted_log_covariance(const ModelStructure& structure,
                                         const std::vector<double>& log_parameters,
                                         double tau0_s, double record_length_s);

// Relative sigma of parameter `parameter_index` (an index into the ln-parameters) predicted for a
// record of record_length_s; infinity if the information is singular.
double predicted_relative_sigma(const ModelStructure& structure,
                                const std::vector<double>& log_parameters, int parameter_index,
                                double tau0_s, double record_length_s);

// Shortest record (s) for which predicted_relative_sigma() <= target, searched from 100 samples
// to 1e4 times current_length_s; infinity if even that is not enough.
double required_record_length_s(const ModelStructure& structure,
                                const std::vector<double>& log_parameters, int parameter_index,
                                double tau0_s, double current_length_s,
                                double target_relative_sigma);

// The record length a fit says it needs for `term_name`'s amplitude to reach the target
// relative sigma. The Cramér-Rao length is scaled by (reported sigma / Cramér-Rao sigma)^2 at the
// current length, so a bootstrap sigma (which sees the octave points' correlation) carries its
// realism over; sigma ~ 1 / sqrt(T) is assumed for that ratio. Infinity if the term is not in
// the model or cannot reach the target. Throws std::invalid_argument for an unknown term.
double required_record_length_s(const FitResult& fit, const std::string& term_name,
                                double target_relative_sigma);

}  // namespace identify
}  // namespace imu_lab
