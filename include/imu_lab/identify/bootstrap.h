// Parametric bootstrap of the identified parameters: records are simulated from the fitted
// model with the emulator's noise processes (record_simulation.h), the overlapping Allan
// deviation is recomputed at the same averaging factors, the same model structure is refitted,
// and the spread of the refits is each parameter's sigma. Unlike the Ceres covariance it carries
// the correlation between octave points and the non-linearity of the fit.
#pragma once

#include <cstdint>
#include <vector>

#include "imu_lab/identify/fit_result.h"

namespace imu_lab {
namespace identify {

struct BootstrapOptions {
  int replicas = 30;
  std::uint64_t seed = 1;
};

struct BootstrapSummary {
  int replicas_used = 0;
  // Per model term (in FitResult::model order): refitted amplitudes and shapes, SI.
  std::vector<std::vector<double>> amplitudes;
  std::vector<std::vector<double>> shapes;  // empty inner vector when the shape is fixed
  std::vector<double> amplitude_sigma;      // sample standard deviation
  std::vector<double> shape_sigma;          // NaN when the shape is fixed
};

// Throws std::invalid_argument if replicas < 2.
BootstrapSummary bootstrap_uncertainty(const FitResult& fit, const BootstrapOptions& options);

// Replaces the model terms' sigmas by the bootstrap's (sigma_source = bootstrap) and re-rates
// terms against options.unconstrained_relative_sigma.
void apply_bootstrap(const BootstrapSummary& summary, FitResult* fit);

}  // namespace identify
}  // namespace imu_lab
