// A flexible description of a measured Allan curve, used only to weigh the points (its
// covariance of the estimates, avar_covariance.h), never reported: white noise, the output
// quantization and a bank of first-order Markov terms with correlation times spread over the
// record, their amplitudes non-negative and fitted linearly (AVAR is linear in each amplitude
// squared) by Lawson and Hanson's non-negative least squares on relative residuals. A sum of
// Markov terms can follow flicker noise, random walk, humps and a front end's roll-off, so the
// weights stand on the data, whichever model the selection then tries (the generalized method of
// wavelet moments estimates them from the data too; Guerrier et al., JASA 2013).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/fit_problem.h"
#include "imu_lab/identify/noise_model.h"

namespace imu_lab {
namespace identify {

NoiseModel descriptive_model(const std::vector<FitPoint>& points, const DataSpan& span,
                             double output_quantization_density);

// min |A x - b| subject to x >= 0 (Lawson and Hanson, "Solving Least Squares Problems", 1974,
// ch. 23).
Eigen::VectorXd non_negative_least_squares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

}  // namespace identify
}  // namespace imu_lab
