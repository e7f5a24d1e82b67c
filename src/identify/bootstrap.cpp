#include "imu_lab/identify/bootstrap.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "imu_lab/allan/batch.h"
#include "imu_lab/identify/profile_likelihood.h"
#include "imu_lab/identify/record_simulation.h"

namespace imu_lab {
namespace identify {

namespace {

double sample_sigma(const std::vector<double>& values) {
  if (values.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  double mean = 0.0;
  for (double v : values) mean += v;
  mean /= values.size();
  double sum = 0.0;
  for (double v : values) sum += (v - mean) * (v - mean);
  return std::sqrt(sum / (values.size() - 1));
}

std::vector<int> fitted_averaging_factors(const FitResult& fit) {
  std::vector<int> factors;
  for (const FitPoint& point : fit.points) {
    factors.push_back(static_cast<int>(std::lround(point.tau_s / fit.tau0_s)));
  }
  return factors;
}

}  // namespace

BootstrapSummary bootstrap_uncertainty(const FitResult& fit, const BootstrapOptions& options) {
  if (options.replicas < 2) throw std::invalid_argument("bootstrap: need at least 2 replicas");
  const long long sample_count = std::llround(fit.record_length_s / fit.tau0_s);
  const std::vector<int> factors = fitted_averaging_factors(fit);
  const DataSpan span{fit.tau0_s, fit.record_length_s, fit.points.front().tau_s,
                      fit.points.back().tau_s};
  const SolverSettings settings = solver_settings(fit.options);
  const size_t term_count = fit.model.terms.size();
  BootstrapSummary summary;
  summary.amplitudes.assign(term_count, {});
  summary.shapes.assign(term_count, {});
  for (int replica = 0; replica < options.replicas; ++replica) {
    const std::vector<double> rates =
        simulate_rates(fit.model, fit.tau0_s, sample_count, options.seed + 7919ULL * replica);
    const auto curve = allan::evaluate_frequency(allan::Statistic::kOverlappingAllan, rates,
                                                 fit.tau0_s, factors);
    std::vector<FitPoint> points;
    try {
      points = select_octave_points(curve);
    } catch (const std::exception&) {
      continue;
    }
    const SolveOutcome outcome =
        refit_structure(points, fit.structure, fit.log_parameters, span, settings);
    if (!outcome.usable) continue;
    const NoiseModel refitted = model_from_log_parameters(fit.structure, outcome.log_parameters);
    for (size_t i = 0; i < term_count; ++i) {
      summary.amplitudes[i].push_back(refitted.terms[i].amplitude);
      if (fit.structure.slots[i].shape_free) summary.shapes[i].push_back(refitted.terms[i].shape);
    }
    ++summary.replicas_used;
  }
  for (size_t i = 0; i < term_count; ++i) {
    summary.amplitude_sigma.push_back(sample_sigma(summary.amplitudes[i]));
    summary.shape_sigma.push_back(sample_sigma(summary.shapes[i]));
  }
  return summary;
}

void apply_bootstrap(const BootstrapSummary& summary, FitResult* fit) {
  for (size_t i = 0; i < fit->model.terms.size() && i < summary.amplitude_sigma.size(); ++i) {
    TermEstimate& term = fit->terms[i];
    term.sigma_source = SigmaSource::kBootstrap;
    term.amplitude.sigma = summary.amplitude_sigma[i];
    if (term.shape_fitted) term.shape.sigma = summary.shape_sigma[i];
    const double relative = term.amplitude.sigma / term.amplitude.value;
    if (term.status == TermStatus::kPresent &&
        !(relative <= fit->options.unconstrained_relative_sigma)) {
      term.status = TermStatus::kUnconstrained;
      const SolverSettings settings = solver_settings(fit->options);
      const DataSpan span{fit->tau0_s, fit->record_length_s, fit->points.front().tau_s,
                          fit->points.back().tau_s};
      term.amplitude.upper_bound = profile_upper_bound(
          fit->points, fit->structure, fit->log_parameters,
          model_cost(fit->points, fit->structure, fit->log_parameters, settings),
          static_cast<int>(i), span, settings, fit->options.upper_bound_confidence);
    }
  }
}

}  // namespace identify
}  // namespace imu_lab
