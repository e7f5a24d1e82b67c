// Noise identification entry point: overlapping-Allan points in, identified noise model out.
// Works on any vector of StabilityPoints (the batch reference or the streaming engine), as long
// as they are overlapping Allan deviations of the rate at integer averaging factors.
#pragma once

#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/identify/fit_options.h"
#include "imu_lab/identify/fit_result.h"

namespace imu_lab {
namespace identify {

// tau0_s: sample interval; record_length_s: duration of the record the points came from.
// Selects the model by the GMM distance with the model's own covariance of the estimates
// (model_selection.h), estimates the discrepancy the model leaves, gives sigmas from the
// moment covariance, bounds absent and unconstrained terms by profile, checks the fitted total
// against the measured curve's band, reads the curve graphically and warns where either
// disagrees with the fit.
// Throws InputError for unusable points, std::invalid_argument for tau0_s or record_length_s <= 0.
FitResult fit_noise_model(const std::vector<allan::StabilityPoint>& points, double tau0_s, double record_length_s,
                          const FitOptions& options = FitOptions());

// The white density the output's rounding adds: step / sqrt(12) per sample.
double quantization_density(double output_step, double tau0_s);

}  // namespace identify
}  // namespace imu_lab
