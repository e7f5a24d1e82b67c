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

double sample_log_sigma(const std::vector<double>& values) {
  if (values.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  double mean = 0.0;
  for (double v : values) mean += std::log(v);
  mean /= values.size();
  double sum = 0.0;
  for (double v : values) sum += (std::log(v) - mean) * (std::log(v) - mean);
  return std::sqrt(sum / (values.size() - 1));
}

}  // namespace

BootstrapSummary bootstrap_uncertainty(const FitResult& fit, const BootstrapOptions& options) {
  if (options.replicas < 2) throw std::invalid_argument("bootstrap: need at least 2 replicas");
  const std::vector<int> factors = averaging_factors(fit.points);
  const size_t term_count = fit.model.terms.size();
  BootstrapSummary summary;
  summary.amplitudes.assign(term_count, {});
  summary.shapes.assign(term_count, {});
  for (int replica = 0; replica < options.replicas; ++replica) {
    const std::vector<double> rates =
        simulate_rates(fit.model, fit.tau0_s, fit.span.sample_count, options.seed + 7919ULL * replica);
    const auto curve = allan::evaluate_frequency(allan::Statistic::kOverlappingAllan, rates, fit.tau0_s, factors);
    std::vector<FitPoint> points;
    for (const auto& point : curve)
      points.push_back({point.tau_s, point.averaging_factor, point.deviation * point.deviation});
    const SolveOutcome outcome = refit_structure(points, fit.structure, fit.log_parameters, fit.span, fit.weights);
    if (!outcome.usable) continue;
    const NoiseModel refitted = model_from_log_parameters(fit.structure, outcome.log_parameters);
    for (size_t i = 0; i < term_count; ++i) {
      summary.amplitudes[i].push_back(refitted.terms[i].amplitude);
      if (fit.structure.slots[i].shape_free) summary.shapes[i].push_back(refitted.terms[i].shape);
    }
    ++summary.replicas_used;
  }
  for (size_t i = 0; i < term_count; ++i) {
    summary.amplitude_log_sigma.push_back(sample_log_sigma(summary.amplitudes[i]));
    summary.shape_log_sigma.push_back(sample_log_sigma(summary.shapes[i]));
  }
  return summary;
}

void apply_bootstrap(const BootstrapSummary& summary, FitResult* fit) {
  for (size_t i = 0; i < fit->model.terms.size() && i < summary.amplitude_log_sigma.size(); ++i) {
    TermEstimate& term = fit->terms[i];
    term.sigma_source = SigmaSource::kBootstrap;
    term.amplitude.log_sigma = summary.amplitude_log_sigma[i];
    term.amplitude.sigma = term.amplitude.value * term.amplitude.log_sigma;
    term.amplitude.structure_mixture.clear();  // the refits' spread stands alone
    if (term.shape_fitted) {
      term.shape.log_sigma = summary.shape_log_sigma[i];
      term.shape.sigma = term.shape.value * term.shape.log_sigma;
      term.shape.structure_mixture.clear();
    }
    if (term.status == TermStatus::kPresent &&
        !(term.amplitude.log_sigma <= fit->options.unconstrained_relative_sigma)) {
      term.status = TermStatus::kUnconstrained;
      term.amplitude.upper_bound =
          profile_upper_bound(fit->points, fit->structure, fit->log_parameters,
                              model_cost(fit->points, fit->structure, fit->log_parameters, fit->weights),
                              static_cast<int>(i), fit->span, fit->weights, fit->options.upper_bound_confidence,
                              &term.amplitude.upper_bound_one_sigma);
    }
  }
}

}  // namespace identify
}  // namespace imu_lab
