#include "imu_lab/identify/fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <cstdlib>

#include "imu_lab/identify/avar_covariance.h"
#include "imu_lab/allan/confidence.h"
#include "imu_lab/identify/chi_squared.h"
#include "imu_lab/identify/descriptive_model.h"
#include "imu_lab/identify/fit_warnings.h"
#include "imu_lab/identify/profile_likelihood.h"
#include "imu_lab/identify/start_values.h"
#include "imu_lab/identify/structure_doubt.h"

namespace imu_lab {
namespace identify {

namespace {

// The first selection assumes the model describes the curve to 1 % in variance (the band's
// +-1 % floor in deviation is twice that); later rounds use the estimated discrepancy.
constexpr double kInitialDiscrepancy = 0.01;
constexpr double kLargestDiscrepancy = 0.1;

double distance_at(const std::vector<FitPoint>& points, const Eigen::MatrixXd& model_covariance,
                   const Eigen::VectorXd& model_values, double discrepancy) {
  return moment_distance(points, model_values, moment_weights(model_values, model_covariance, discrepancy));
}

// The relative spread to add to every point's variance so that the distance at the estimate
// equals its degrees of freedom (the quasi-likelihood dispersion); 0 when the distance is within
// two standard deviations of its chi-squared expectation.
double estimate_discrepancy(const std::vector<FitPoint>& points, const NoiseModel& model,
                            OavarCovariance& model_covariance, int degrees_of_freedom) {
  Eigen::VectorXd values(points.size());
  for (size_t k = 0; k < points.size(); ++k) values(k) = model_avar(model, points[k].tau_s);
  const Eigen::MatrixXd covariance = model_covariance.covariance(model);
  const auto distance = [&](double discrepancy) { return distance_at(points, covariance, values, discrepancy); };
  const double dof = std::max(1, degrees_of_freedom);
  if (distance(0.0) <= dof + 2.0 * std::sqrt(2.0 * dof)) return 0.0;
  // Beyond 10 % in AVAR the model does not describe the curve at all; the band check says where.
  double low = std::log(1e-6), high = std::log(kLargestDiscrepancy);
  if (distance(std::exp(high)) > dof) return std::exp(high);
  for (int iteration = 0; iteration < 40; ++iteration) {
    const double middle = 0.5 * (low + high);
    if (distance(std::exp(middle)) > dof) {
      low = middle;
    } else {
      high = middle;
    }
  }
  return std::exp(high);
}

FitQuality assess_quality(double cost, int points, int parameters, double discrepancy) {
  FitQuality quality;
  quality.distance = 2.0 * cost;
  quality.points = points;
  quality.parameters = parameters;
  quality.degrees_of_freedom = std::max(1, points - parameters);
  quality.distance_per_dof = quality.distance / quality.degrees_of_freedom;
  quality.p_value = chi_squared_upper_tail(quality.distance, quality.degrees_of_freedom);
  quality.discrepancy = discrepancy;
  return quality;
}

// The estimate of the combination c' ln(theta) of the fit's log-parameters: its sigma from the
// (widened) covariance and, where alternatives were weighed, the mixture its intervals come from.
void set_log_uncertainty(const FitResult& fit, const Eigen::MatrixXd& selected_log_covariance,
                         const Eigen::VectorXd& combination, ParameterEstimate* estimate) {
  estimate->log_sigma = std::sqrt(std::max(0.0, combination.dot(fit.log_covariance * combination)));
  estimate->sigma = estimate->value * estimate->log_sigma;
  if (!fit.structure_alternatives.empty()) {
    estimate->structure_mixture = structure_mixture(fit.structure_alternatives, selected_log_covariance, combination);
  }
}

// The combination picking log-parameters `first` (and `second`, when given) of the fit.
Eigen::VectorXd log_parameter_sum(const FitResult& fit, int first, int second = -1) {
  Eigen::VectorXd combination = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(fit.log_parameters.size()));
  combination(first) = 1.0;
  if (second >= 0) combination(second) += 1.0;
  return combination;
}

// Terms of the selected model, with moment-covariance sigmas and, when too loose, a profile bound.
void describe_model_terms(const SelectedModel& selected, const DataSpan& span,
                          const Eigen::MatrixXd& selected_log_covariance, FitResult* fit) {
  const std::vector<std::string> names = term_names(fit->model);
  for (size_t i = 0; i < fit->model.terms.size(); ++i) {
    const Term& term = fit->model.terms[i];
    const TermSlot& slot = fit->structure.slots[i];
    const int offset = parameter_offset(fit->structure, static_cast<int>(i));
    TermEstimate estimate;
    estimate.name = names[i];
    estimate.kind = term.kind;
    estimate.status = TermStatus::kPresent;
    estimate.sigma_source = SigmaSource::kMomentCovariance;
    estimate.amplitude.value = term.amplitude;
    set_log_uncertainty(*fit, selected_log_covariance, log_parameter_sum(*fit, offset), &estimate.amplitude);
    estimate.shape_fitted = slot.shape_free;
    if (has_shape(term.kind) && term.shape > 0.0) estimate.shape.value = term.shape;
    if (slot.shape_free) {
      set_log_uncertainty(*fit, selected_log_covariance, log_parameter_sum(*fit, offset + 1), &estimate.shape);
    }
    if (term.kind == TermKind::kResonance) {
      estimate.width.value = term.width;
      // ln width = ln f_n + ln(width / f_n)
      set_log_uncertainty(*fit, selected_log_covariance, log_parameter_sum(*fit, offset + 1, offset + 2),
                          &estimate.width);
    }
    estimate.selection_statistic = selected.removal_lr_statistics[i];
    estimate.selection_threshold = selected.removal_thresholds[i];
    estimate.borderline = is_borderline(estimate.selection_statistic, estimate.selection_threshold, true);
    if (!(estimate.amplitude.log_sigma <= fit->options.unconstrained_relative_sigma)) {
      estimate.status = TermStatus::kUnconstrained;
      estimate.amplitude.upper_bound =
          profile_upper_bound(fit->points, fit->structure, fit->log_parameters, selected.cost, static_cast<int>(i),
                              span, selected.weights, fit->options.upper_bound_confidence,
                              &estimate.amplitude.upper_bound_one_sigma);
    }
    fit->terms.push_back(estimate);
  }
}

// Four of the selection's start shapes spread over its range (first, last and two between).
std::vector<Term> spread_start_shapes(const TermSlot& slot, const std::vector<FitPoint>& points, const DataSpan& span) {
  constexpr size_t kStarts = 4;
  const std::vector<Term> all = start_shapes(slot, points, span);
  if (all.size() <= kStarts) return all;
  std::vector<Term> spread;
  for (size_t i = 0; i < kStarts; ++i) spread.push_back(all[i * (all.size() - 1) / (kStarts - 1)]);
  return spread;
}

// A Markov term, sinusoid or resonance the selection left out: absent, with the largest
// amplitude any shape could carry (shaped_profile_upper_bound); its shape stays unreported. Its
// selection statistic is the fall of the distance its addition brings, fitted as the selection
// fits a candidate (the left-out Markov term's fit is fit_left_out_terms'), so that a term the
// selection nearly took is marked borderline like any other.
void describe_absent_shaped_term(const SelectedModel& selected, const DataSpan& span, const TermSlot& slot,
                                 const std::vector<TermAddition>& additions, FitResult* fit) {
  TermEstimate estimate;
  estimate.name = term_kind_name(slot.kind);
  estimate.kind = slot.kind;
  estimate.status = TermStatus::kAbsent;
  estimate.amplitude.upper_bound = shaped_profile_upper_bound(
      fit->points, fit->structure, fit->log_parameters, selected.cost, spread_start_shapes(slot, fit->points, span),
      span, selected.weights, fit->options.upper_bound_confidence, &estimate.amplitude.upper_bound_one_sigma);
  const auto fitted = std::find_if(additions.begin(), additions.end(),
                                   [&](const TermAddition& addition) { return addition.kind == slot.kind; });
  if (fitted != additions.end()) {
    estimate.selection_statistic = std::max(0.0, 2.0 * (selected.cost - fitted->outcome.cost));
  } else if (slot.kind == TermKind::kMarkov) {
    estimate.selection_statistic = 0.0;  // fitted, but kept only where it lowered the distance
  } else {
    ModelStructure extended;
    const SolveOutcome added = fit_with_new_slot(fit->points, span, fit->options, fit->structure, fit->log_parameters,
                                                 slot, selected.weights, &extended);
    if (added.usable) estimate.selection_statistic = std::max(0.0, 2.0 * (selected.cost - added.cost));
  }
  if (std::isfinite(estimate.selection_statistic)) {
    estimate.selection_threshold = slot_lr_threshold(fit->options, slot, static_cast<int>(fit->points.size()));
    estimate.borderline = is_borderline(estimate.selection_statistic, estimate.selection_threshold, false);
  }
  fit->terms.push_back(estimate);
}

// The slot a left-out candidate is bounded and added in: one-parameter kinds only (shaped ones
// get describe_absent_shaped_term, the zero-DC family no bound); a fitted-cutoff bias
// instability at the Nyquist cutoff. False for the others.
bool one_parameter_slot(TermSlot* slot, double tau0_s) {
  if (slot->kind == TermKind::kMarkov || slot->kind == TermKind::kSinusoid || slot->kind == TermKind::kResonance) {
    return false;
  }
  if (shape_count(slot->kind) > 0 && slot->kind != TermKind::kBiasInstability && slot->kind != TermKind::kWhiteRate) {
    return false;
  }
  if (slot->shape_free) {
    slot->shape_free = false;
    slot->fixed_shape = 1.0 / (2.0 * tau0_s);
  }
  return true;
}

// The candidate kinds the selection left out, each once, in candidate order.
std::vector<TermSlot> left_out_slots(const FitResult& fit, const DataSpan& span) {
  std::vector<TermSlot> left_out;
  for (const TermSlot& slot : candidate_slots(fit.options, span)) {
    bool seen = false;
    for (const Term& term : fit.model.terms) seen = seen || term.kind == slot.kind;
    for (const TermSlot& earlier : left_out) seen = seen || earlier.kind == slot.kind;
    if (!seen) left_out.push_back(slot);
  }
  return left_out;
}

// Each left-out one-parameter term fitted freely beside the selected ones, from a negligible
// amplitude: its selection statistic, and an alternative structure for the sigmas. A left-out
// Markov term is fitted as the selection fits a candidate (its correlation time searched) and
// kept where it lowers J: a slow hump on a floor of bias instability that the selection's
// threshold for a searched shape left out moves B (doc/identification.md, "Doubt").
std::vector<TermAddition> fit_left_out_terms(const SelectedModel& selected, const DataSpan& span,
                                             const FitResult& fit) {
  std::vector<TermAddition> additions;
  for (TermSlot slot : left_out_slots(fit, span)) {
    TermAddition addition;
    addition.kind = slot.kind;
    if (slot.kind == TermKind::kMarkov) {
      addition.outcome = fit_with_new_slot(fit.points, span, fit.options, fit.structure, fit.log_parameters, slot,
                                           selected.weights, &addition.structure);
      if (addition.outcome.usable && addition.outcome.cost < selected.cost) additions.push_back(addition);
      continue;
    }
    if (!one_parameter_slot(&slot, fit.tau0_s)) continue;
    addition.structure = fit.structure;
    std::vector<double> log_parameters = fit.log_parameters;
    append_negligible_slot(fit.points, slot, &addition.structure, &log_parameters);
    addition.outcome = refit_structure(fit.points, addition.structure, log_parameters, span, selected.weights);
    additions.push_back(addition);
  }
  return additions;
}

// A Markov term of the selected model whose correlation time is long carries a rise that a
// left-out K or R would carry (over the record's taus their AVARs grow alike), and the profile
// bound, which keeps the Markov term, then lies below the value the structure with the Markov
// term replaced by the left-out one finds. Each such swap is weighed against the selected
// structure by Akaike's criterion on the GMM distance (as structure_doubt.h weighs its
// alternatives, here pairwise), and its lognormal may hold at most its weight's share of the
// bound's tail: the bound rises to the swap's quantile at 1 - tail / weight where that lies
// above it (doc/identification.md, "Bounds of a K carried by a Markov term").
void widen_bound_by_markov_swaps(const SelectedModel& selected, const DataSpan& span, const TermSlot& slot,
                                 const FitResult& fit, ParameterEstimate* amplitude) {
  for (size_t swapped_out = 0; swapped_out < fit.structure.slots.size(); ++swapped_out) {
    if (fit.structure.slots[swapped_out].kind != TermKind::kMarkov) continue;
    ModelStructure swapped = fit.structure;
    std::vector<double> start = fit.log_parameters;
    remove_slot(swapped, start, static_cast<int>(swapped_out));
    append_negligible_slot(fit.points, slot, &swapped, &start);
    const SolveOutcome outcome = refit_structure(fit.points, swapped, start, span, selected.weights);
    if (!outcome.usable) continue;
    const double criterion_change = 2.0 * (outcome.cost - selected.cost) +
                                    2.0 * (parameter_count(swapped) - parameter_count(fit.structure));
    const double weight = 1.0 / (1.0 + std::exp(0.5 * criterion_change));
    const int index = parameter_count(swapped) - 1;
    const Eigen::MatrixXd covariance =
        log_parameter_covariance(fit.points, swapped, outcome.log_parameters, selected.weights);
    const double log_sigma = std::sqrt(covariance(index, index));
    // A swap that leaves the term loose says no more than the profile: its quantiles would run
    // off to any size.
    if (!(log_sigma <= fit.options.unconstrained_relative_sigma)) continue;
    const auto raise = [&](double tail, double* bound) {
      if (!(weight > tail)) return;
      // The normal's quantile at p = 1 - tail / weight: z^2 is chi-squared(1) at |2p - 1|, z of
      // the sign of p - 1/2.
      const double centred = 1.0 - 2.0 * tail / weight;
      const double z = std::copysign(std::sqrt(chi_squared_quantile(std::abs(centred), 1.0)), centred);
      const double candidate = std::exp(outcome.log_parameters[index] + z * log_sigma);
      if (!(candidate <= *bound)) *bound = candidate;
    };
    raise(1.0 - fit.options.upper_bound_confidence, &amplitude->upper_bound);
    raise(1.0 - kOneSigmaConfidence, &amplitude->upper_bound_one_sigma);
  }
}

// Candidate terms the selection left out: absent, with a profile upper bound and, for
// one-parameter terms, the fall of the distance their free addition would bring.
void describe_absent_terms(const SelectedModel& selected, const DataSpan& span,
                           const std::vector<TermAddition>& additions, FitResult* fit) {
  for (TermSlot slot : left_out_slots(*fit, span)) {
    if (slot.kind == TermKind::kMarkov || slot.kind == TermKind::kSinusoid || slot.kind == TermKind::kResonance) {
      describe_absent_shaped_term(selected, span, slot, additions, fit);
      continue;
    }
    if (!one_parameter_slot(&slot, fit->tau0_s)) continue;
    const auto addition = std::find_if(additions.begin(), additions.end(),
                                       [&](const TermAddition& added) { return added.kind == slot.kind; });
    ModelStructure structure = fit->structure;
    std::vector<double> log_parameters = fit->log_parameters;
    append_negligible_slot(fit->points, slot, &structure, &log_parameters);
    TermEstimate estimate;
    estimate.name = term_kind_name(slot.kind);
    estimate.kind = slot.kind;
    estimate.status = TermStatus::kAbsent;
    if (has_shape(slot.kind) && slot.fixed_shape > 0.0) estimate.shape.value = slot.fixed_shape;
    const int slot_index = static_cast<int>(structure.slots.size()) - 1;
    estimate.amplitude.upper_bound =
        profile_upper_bound(fit->points, structure, log_parameters, selected.cost, slot_index, span, selected.weights,
                            fit->options.upper_bound_confidence, &estimate.amplitude.upper_bound_one_sigma);
    if (slot.kind == TermKind::kRandomWalk || slot.kind == TermKind::kRateRamp) {
      widen_bound_by_markov_swaps(selected, span, slot, *fit, &estimate.amplitude);
    }
    if (addition != additions.end() && addition->outcome.usable) {
      estimate.selection_statistic = std::max(0.0, 2.0 * (selected.cost - addition->outcome.cost));
      estimate.selection_threshold = slot_lr_threshold(fit->options, slot, static_cast<int>(fit->points.size()));
      estimate.borderline = is_borderline(estimate.selection_statistic, estimate.selection_threshold, false);
    }
    fit->terms.push_back(estimate);
  }
}

std::vector<BandPoint> band_check(const std::vector<allan::StabilityPoint>& curve, const NoiseModel& model,
                                  const DataSpan& span) {
  std::vector<int> factors;
  std::vector<double> fractions;
  std::vector<const allan::StabilityPoint*> usable;
  for (const auto& point : curve) {
    if (!(std::isfinite(point.deviation) && point.deviation > 0.0) || point.averaging_factor < 1 ||
        2LL * point.averaging_factor > span.sample_count - 1) {
      continue;
    }
    factors.push_back(point.averaging_factor);
    fractions.push_back(point.pooled_term_fraction);
    usable.push_back(&point);
  }
  OavarCovariance covariance(factors, span.tau0_s, span.sample_count);
  covariance.set_pooled_term_fractions(fractions);
  const std::vector<double> variance = covariance.variance(model);
  std::vector<BandPoint> band;
  for (size_t k = 0; k < usable.size(); ++k) {
    BandPoint point;
    point.tau_s = usable[k]->tau_s;
    point.measured_deviation = usable[k]->deviation;
    const double fitted_avar = model_avar(model, point.tau_s);
    point.fitted_deviation = std::sqrt(fitted_avar);
    point.edf = variance[k] > 0.0 ? 2.0 * fitted_avar * fitted_avar / variance[k] : 1e12;
    const BandLimits limits = band_limits(point.measured_deviation, point.edf);
    point.lower = limits.lower;
    point.upper = limits.upper;
    band.push_back(point);
  }
  return band;
}

}  // namespace

double quantization_density(double output_step, double tau0_s) {
  return output_step > 0.0 ? output_step / std::sqrt(12.0) * std::sqrt(tau0_s) : 0.0;
}

namespace {
// One fewer term of this kind may enter: the count of a numbered kind drops below the model's.
void leave_out_one(TermKind kind, const NoiseModel& model, FitOptions* options) {
  int in_model = 0;
  for (const Term& term : model.terms) in_model += term.kind == kind ? 1 : 0;
  switch (kind) {
    case TermKind::kWhiteAngle: options->allow_white_angle = false; break;
    case TermKind::kWhiteRate: break;  // never left out
    case TermKind::kBiasInstability: options->allow_bias_instability = false; break;
    case TermKind::kRandomWalk: options->allow_random_walk = false; break;
    case TermKind::kRateRamp: options->allow_rate_ramp = false; break;
    case TermKind::kMarkov: options->max_markov_terms = in_model - 1; break;
    case TermKind::kSinusoid: options->max_sinusoids = in_model - 1; break;
    case TermKind::kResonance: options->max_resonances = in_model - 1; break;
    case TermKind::kZeroDcFamily: options->allow_zero_dc_family = false; break;
    case TermKind::kZeroDcGaussian: options->allow_zero_dc_gaussian = false; break;
    case TermKind::kHighPassWhite: options->allow_high_pass_white = false; break;
  }
}
}  // namespace

std::vector<std::string> zero_dc_term_names() {
  return {term_kind_name(TermKind::kZeroDcFamily), term_kind_name(TermKind::kZeroDcGaussian),
          term_kind_name(TermKind::kHighPassWhite)};
}

void allow_zero_dc_term(const std::string& term_name, FitOptions* options) {
  if (term_name == term_kind_name(TermKind::kZeroDcFamily)) {
    options->allow_zero_dc_family = true;
  } else if (term_name == term_kind_name(TermKind::kZeroDcGaussian)) {
    options->allow_zero_dc_gaussian = true;
  } else if (term_name == term_kind_name(TermKind::kHighPassWhite)) {
    options->allow_high_pass_white = true;
  } else {
    std::string known;
    for (const std::string& name : zero_dc_term_names()) known += (known.empty() ? "" : ", ") + name;
    throw std::invalid_argument("zero-at-DC term '" + term_name + "' is not one of " + known);
  }
}

BandLimits band_limits(double measured_deviation, double edf) {
  const allan::DeviationBounds bounds =
      allan::chi_squared_bounds(measured_deviation, std::min(edf, 1e12), kBandConfidence);
  return {std::min((1.0 - kBandMinimumHalfWidth) * measured_deviation, bounds.lower),
          std::max((1.0 + kBandMinimumHalfWidth) * measured_deviation, bounds.upper)};
}

double ParameterEstimate::interval_low(double z) const {
  if (structure_mixture.empty()) return value * std::exp(-z * log_sigma);
  return value * std::exp(mixture_log_quantile(structure_mixture, 0.5 * std::erfc(z / std::sqrt(2.0))));
}

double ParameterEstimate::interval_high(double z) const {
  if (structure_mixture.empty()) return value * std::exp(z * log_sigma);
  return value * std::exp(mixture_log_quantile(structure_mixture, 0.5 * std::erfc(-z / std::sqrt(2.0))));
}

std::string term_status_name(TermStatus status) {
  static const char* const kNames[] = {"present", "unconstrained", "absent"};
  return kNames[static_cast<int>(status)];
}

std::string sigma_source_name(SigmaSource source) {
  static const char* const kNames[] = {"none", "moment_covariance", "bootstrap"};
  return kNames[static_cast<int>(source)];
}

std::vector<const TermEstimate*> terms_in_report_order(const FitResult& fit) {
  std::vector<const TermEstimate*> ordered;
  for (TermKind kind : {TermKind::kWhiteRate, TermKind::kBiasInstability, TermKind::kRandomWalk, TermKind::kWhiteAngle,
                        TermKind::kRateRamp}) {
    for (const TermEstimate& term : fit.terms) {
      if (term.kind == kind) ordered.push_back(&term);
    }
  }
  for (const TermEstimate& term : fit.terms) {
    if (std::find(ordered.begin(), ordered.end(), &term) == ordered.end()) ordered.push_back(&term);
  }
  return ordered;
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

FitResult fit_noise_model(const std::vector<allan::StabilityPoint>& points, double tau0_s, double record_length_s,
                          const FitOptions& options) {
  if (!(tau0_s > 0.0) || !(record_length_s > tau0_s)) {
    throw std::invalid_argument("fit_noise_model: need tau0_s > 0 and record_length_s > tau0_s");
  }
  FitResult fit;
  fit.options = options;
  fit.tau0_s = tau0_s;
  fit.record_length_s = record_length_s;
  DataSpan span;
  span.tau0_s = tau0_s;
  span.record_length_s = record_length_s;
  span.sample_count = std::llround(record_length_s / tau0_s);
  std::vector<allan::StabilityPoint> evaluable;
  for (const auto& point : points) {
    if (2LL * point.averaging_factor <= span.sample_count - 1) evaluable.push_back(point);
  }
  fit.points = select_fit_points(evaluable);
  fit.graphical = read_graphically(points);
  span.tau_min_s = fit.points.front().tau_s;
  span.tau_max_s = fit.points.back().tau_s;
  span.smallest_avar = span.largest_avar = fit.points.front().avar;
  for (const FitPoint& point : fit.points) {
    span.smallest_avar = std::min(span.smallest_avar, point.avar);
    span.largest_avar = std::max(span.largest_avar, point.avar);
  }
  const double quantization = quantization_density(options.output_quantization_step, tau0_s);

  OavarCovariance covariance(averaging_factors(fit.points), tau0_s, span.sample_count);
  covariance.set_pooled_term_fractions(pooled_term_fractions(fit.points));
  // The weights stand on a description of the data (descriptive_model.h). The selection first
  // asks the model to describe the curve to 1 % in AVAR (the band's floor is +-1 % in
  // deviation); the spread the selected structure leaves is then measured at its refit without
  // one, since the fit under the 1 % spread is off by many sigma at the short taus, whose
  // estimates are far more precise. Under 1 % (a model that is right, as on the emulator) the
  // selection runs again with it, so the estimates' full precision decides. At 1 % or more the
  // selection looks again at that precision (a mode taken for a line, or missed, shows only at
  // the shortest taus) and keeps what it finds if that leaves under 1 %; otherwise the terms stay
  // as selected and only their fit and sigmas take the larger spread (selecting again under it
  // would drop terms, raise the spread, and spiral). doc/identification.md, "Model discrepancy".
  const NoiseModel first_weight_model = descriptive_model(fit.points, span, quantization);
  const auto spread_left_by = [&](const SelectedModel& model) {
    const int dof = static_cast<int>(fit.points.size()) - parameter_count(model.structure);
    return estimate_discrepancy(fit.points, model_from_log_parameters(model.structure, model.log_parameters),
                                covariance, dof);
  };
  const auto select_terms = [&](const FitOptions& allowed) {
    SelectedModel selected =
        select_model(fit.points, span, allowed, covariance, kInitialDiscrepancy, first_weight_model);
    SelectedModel exact = selected;
    reweigh_selected(fit.points, span, allowed, covariance, 0.0, &exact);
    double discrepancy = spread_left_by(exact);
    if (discrepancy >= kInitialDiscrepancy) {
      SelectedModel precise = exact;
      swap_lines_for_modes(fit.points, span, allowed, covariance, 0.0, &precise);
      precise = select_model(fit.points, span, allowed, covariance, 0.0,
                             model_from_log_parameters(exact.structure, exact.log_parameters), &precise);
      const double precise_discrepancy = spread_left_by(precise);
      if (precise_discrepancy < kInitialDiscrepancy) {
        exact = precise;
        discrepancy = precise_discrepancy;
      }
    }
    if (discrepancy < kInitialDiscrepancy) {
      // A line the first spread let stand for a mode is weighed as the mode at the estimates' own
      // precision here too, not only where it leaves a spread: whether it does is a matter of
      // the other points (how far the longest taus, at a few EDF, happen to lie off).
      SelectedModel swapped = exact;
      if (swap_lines_for_modes(fit.points, span, allowed, covariance, 0.0, &swapped)) {
        const double swapped_discrepancy = spread_left_by(swapped);
        if (swapped_discrepancy < kInitialDiscrepancy) {
          exact = swapped;
          discrepancy = swapped_discrepancy;
        }
      }
      SelectedModel reselected = select_model(fit.points, span, allowed, covariance, discrepancy,
                                              model_from_log_parameters(exact.structure, exact.log_parameters), &exact);
      // The spread was measured on the first structure; one the selection changed (a line the
      // 1 % spread hid, now taken) may describe the curve better, and keeping the old spread
      // would understate the precision its terms have. Measured again while it falls.
      constexpr int kMaxRemeasures = 2;
      for (int remeasure = 0; remeasure < kMaxRemeasures && discrepancy > 0.0 &&
                              !same_structure(reselected.structure, exact.structure);
           ++remeasure) {
        SelectedModel remeasured = reselected;
        reweigh_selected(fit.points, span, allowed, covariance, 0.0, &remeasured);
        const double remeasured_discrepancy = spread_left_by(remeasured);
        if (!(remeasured_discrepancy < discrepancy)) break;
        exact = remeasured;
        discrepancy = remeasured_discrepancy;
        reselected = select_model(fit.points, span, allowed, covariance, discrepancy,
                                  model_from_log_parameters(exact.structure, exact.log_parameters), &exact);
      }
      return reselected;
    }
    discrepancy = spread_left_by(selected);
    if (discrepancy < kInitialDiscrepancy) {
      selected = select_model(fit.points, span, allowed, covariance, discrepancy,
                              model_from_log_parameters(selected.structure, selected.log_parameters), &selected);
    } else {
      refit_selected(fit.points, span, allowed, covariance, discrepancy, &selected);
    }
    return selected;
  };
  // A mode that a line describes at least as well, with a parameter fewer, is taken as the line.
  const auto select = [&](const FitOptions& allowed) {
    SelectedModel selected = select_terms(allowed);
    swap_dominated_modes_for_lines(fit.points, span, allowed, covariance, selected.weights.discrepancy, &selected);
    return selected;
  };
  // A term that claims more than the curve holds is not reported present: its kind is left out
  // and the selection runs again (a few times at most; a model that still claims is warned about).
  constexpr int kMaxReselections = 3;
  FitOptions allowed = options;
  SelectedModel selected = select(allowed);
  for (int attempt = 0; attempt < kMaxReselections; ++attempt) {
    const NoiseModel model = model_from_log_parameters(selected.structure, selected.log_parameters);
    const int claiming = term_claiming_more_than_the_curve(fit.points, model, selected.weights);
    if (claiming < 0) break;
    leave_out_one(model.terms[claiming].kind, model, &allowed);
    selected = select(allowed);
  }
  fit.span = span;
  fit.weights = selected.weights;
  fit.structure = selected.structure;
  fit.log_parameters = selected.log_parameters;
  fit.selection_steps = selected.steps;
  fit.model = model_from_log_parameters(fit.structure, fit.log_parameters);
  fit.log_covariance = log_parameter_covariance(fit.points, fit.structure, fit.log_parameters, selected.weights);
  const Eigen::MatrixXd selected_log_covariance = fit.log_covariance;
  const std::vector<TermAddition> additions = fit_left_out_terms(selected, span, fit);
  fit.structure_alternatives =
      weigh_structure_alternatives(fit.points, span, allowed, fit.structure, fit.log_parameters, selected.cost,
                                   selected.weights, additions, &fit.log_covariance);
  fit.quality = assess_quality(selected.cost, static_cast<int>(fit.points.size()), parameter_count(fit.structure),
                               selected.weights.discrepancy);
  describe_model_terms(selected, span, selected_log_covariance, &fit);
  describe_absent_terms(selected, span, additions, &fit);
  fit.band = band_check(evaluable, fit.model, span);
  fit.findings = fit_findings(fit);
  fit.warnings = fit_warnings(fit.findings);
  return fit;
}

}  // namespace identify
}  // namespace imu_lab
