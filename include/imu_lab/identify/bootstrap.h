// Parametric bootstrap of the identified parameters: records are simulated from the fitted
// model with the emulator's noise processes (record_simulation.h), the overlapping Allan
// variance is recomputed at the fit's averaging factors, the same model structure is refitted
// under the fit's weights, and the spread of the refits (of the logarithms, as the default
// sigmas) is each parameter's sigma. An option beside the default moment-covariance sigmas:
// slow, and it carries the fit's non-linearity where the default is first order.
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
  std::vector<double> amplitude_log_sigma;  // sample standard deviation of ln(amplitude)
  std::vector<double> shape_log_sigma;      // NaN when the shape is fixed
};

// Throws std::invalid_argument if replicas < 2, or for a model the emulator cannot simulate.
BootstrapSummary bootstrap_uncertainty(const FitResult& fit, const BootstrapOptions& options);

// Replaces the model terms' sigmas by the bootstrap's (sigma_source = bootstrap) and re-rates
// terms against options.unconstrained_relative_sigma.
void apply_bootstrap(const BootstrapSummary& summary, FitResult* fit);

}  // namespace identify
}  // namespace imu_lab
