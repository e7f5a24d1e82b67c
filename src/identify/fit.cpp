#include "imu_lab/identify/fit.h"

#include <cmath>
#include <stdexcept>

#include "imu_lab/identify/avar_likelihood.h"
#include "imu_lab/identify/fit_warnings.h"
#include "imu_lab/identify/profile_likelihood.h"

namespace imu_lab {
namespace identify {

namespace {

FitQuality assess_quality(const std::vector<FitPoint>& points, const NoiseModel& model,
                          int parameters) {
  FitQuality quality;
  for (const FitPoint& point : points) {
    quality.deviance += point_deviance(point.avar, model_avar(model, point.tau_s), point.edf);
  }
  quality.points = static_cast<int>(points.size());
  quality.parameters = parameters;
  quality.degrees_of_freedom = std::max(1, quality.points - parameters);
  quality.deviance_per_dof = quality.deviance / quality.degrees_of_freedom;
  quality.p_value = chi_squared_upper_tail(quality.deviance, quality.degrees_of_freedom);
  return quality;
}

// Terms of the selected model, with Ceres sigmas and, when too loose, a profile bound.
void describe_model_terms(const SelectedModel& selected, const DataSpan& span,
                          const SolverSettings& settings, FitResult* fit) {
  const bool have_covariance = fit->log_covariance.size() > 0;
  const std::vector<std::string> names = term_names(fit->model);
  for (size_t i = 0; i < fit->model.terms.size(); ++i) {
    const Term& term = fit->model.terms[i];
    const TermSlot& slot = fit->structure.slots[i];
    const int offset = parameter_offset(fit->structure, static_cast<int>(i));
    TermEstimate estimate;
    estimate.name = names[i];
    estimate.kind = term.kind;
    estimate.status = TermStatus::kPresent;
    estimate.amplitude.value = term.amplitude;
    estimate.shape_fitted = slot.shape_free;
    if (has_shape(term.kind)) estimate.shape.value = term.shape;
    estimate.removal_lr_statistic = selected.removal_lr_statistics[i];
    if (have_covariance) {
      estimate.sigma_source = SigmaSource::kCeresCovariance;
      const double relative = std::sqrt(std::max(0.0, fit->log_covariance(offset, offset)));
      estimate.amplitude.sigma = term.amplitude * relative;
      if (slot.shape_free) {
        estimate.shape.sigma =
            term.shape * std::sqrt(std::max(0.0, fit->log_covariance(offset + 1, offset + 1)));
      }
      if (!(relative <= fit->options.unconstrained_relative_sigma)) {
        estimate.status = TermStatus::kUnconstrained;
      }
    }
    if (estimate.status == TermStatus::kUnconstrained) {
      estimate.amplitude.upper_bound = profile_upper_bound(
          fit->points, fit->structure, fit->log_parameters, selected.cost, static_cast<int>(i),
          span, settings, fit->options.upper_bound_confidence);
    }
    fit->terms.push_back(estimate);
  }
}

// Candidate one-parameter terms the selection left out: absent, with a profile upper bound.
void describe_absent_terms(const SelectedModel& selected, const DataSpan& span,
                           const SolverSettings& settings, FitResult* fit) {
  for (TermSlot slot : candidate_slots(fit->options, span)) {
    if (slot.kind == TermKind::kMarkov || slot.kind == TermKind::kSinusoid ||
        slot.kind == TermKind::kZeroDcFamily) {
      continue;  // two-parameter terms: no single amplitude to bound
    }
    bool in_model = false;
    for (const Term& term : fit->model.terms) in_model = in_model || term.kind == slot.kind;
    if (in_model) continue;
    if (slot.shape_free) {  // bound a fitted-cutoff bias instability at the Nyquist cutoff
      slot.shape_free = false;
      slot.fixed_shape = 1.0 / (2.0 * fit->tau0_s);
    }
    ModelStructure structure = fit->structure;
    std::vector<double> log_parameters = fit->log_parameters;
    append_negligible_slot(fit->points, slot, &structure, &log_parameters);
    TermEstimate estimate;
    estimate.name = term_kind_name(slot.kind);
    estimate.kind = slot.kind;
    estimate.status = TermStatus::kAbsent;
    if (has_shape(slot.kind)) estimate.shape.value = slot.fixed_shape;
    estimate.amplitude.upper_bound = profile_upper_bound(
        fit->points, structure, log_parameters, selected.cost,
        static_cast<int>(structure.slots.size()) - 1, span, settings,
        fit->options.upper_bound_confidence);
    fit->terms.push_back(estimate);
  }
}

}  // namespace

std::string term_status_name(TermStatus status) {
  static const char* const kNames[] = {"present", "unconstrained", "absent"};
  return kNames[static_cast<int>(status)];
}

std::string sigma_source_name(SigmaSource source) {
  static const char* const kNames[] = {"none", "ceres_covariance", "bootstrap"};
  return kNames[static_cast<int>(source)];
}

const TermEstimate* FitResult::find(const std::string& name) const {
  for (const TermEstimate& term : terms) {
    if (term.name == name) return &term;
  }
  return nullptr;
}

TermEstimate* FitResult::find(const std::string& name) {
  return const_cast<TermEstimate*>(static_cast<const FitResult*>(this)->find(name));
}

FitResult fit_noise_model(const std::vector<allan::StabilityPoint>& points, double tau0_s,
                          double record_length_s, const FitOptions& options) {
  if (!(tau0_s > 0.0) || !(record_length_s > tau0_s)) {
    throw std::invalid_argument("fit_noise_model: need tau0_s > 0 and record_length_s > tau0_s");
  }
  FitResult fit;
  fit.options = options;
  fit.tau0_s = tau0_s;
  fit.record_length_s = record_length_s;
  fit.points = select_octave_points(points);
  fit.graphical = read_graphically(points);
  const DataSpan span{tau0_s, record_length_s, fit.points.front().tau_s, fit.points.back().tau_s};
  const SolverSettings settings = solver_settings(options);

  const SelectedModel selected = select_model(fit.points, span, options);
  fit.structure = selected.structure;
  fit.log_parameters = selected.log_parameters;
  fit.selection_steps = selected.steps;
  fit.model = model_from_log_parameters(fit.structure, fit.log_parameters);
  if (!log_parameter_covariance(fit.points, fit.structure, fit.log_parameters, settings,
                                &fit.log_covariance)) {
    fit.log_covariance.resize(0, 0);
  }
  fit.quality = assess_quality(fit.points, fit.model, parameter_count(fit.structure));
  describe_model_terms(selected, span, settings, &fit);
  describe_absent_terms(selected, span, settings, &fit);
  fit.warnings = fit_warnings(fit);
  if (fit.log_covariance.size() == 0) {
    fit.warnings.push_back("Ceres could not compute the covariance: sigmas are missing; run the "
                           "bootstrap");
  }
  return fit;
}

}  // namespace identify
}  // namespace imu_lab
