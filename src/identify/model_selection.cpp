#include "imu_lab/identify/model_selection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdlib>

#include "imu_lab/identify/chi_squared.h"
#include "imu_lab/identify/fit_result.h"
#include "imu_lab/identify/start_values.h"

namespace imu_lab {
namespace identify {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The same parameters with every amplitude multiplied by `factor` (shapes untouched).
std::vector<double> scaled_amplitudes(const ModelStructure& structure, std::vector<double> log_parameters,
                                      double factor) {
  for (size_t i = 0; i < structure.slots.size(); ++i) {
    log_parameters[parameter_offset(structure, static_cast<int>(i))] += std::log(factor);
  }
  return log_parameters;
}

SolveOutcome best_of(const std::vector<FitPoint>& points, const ModelStructure& structure,
                     const std::vector<std::vector<double>>& starts, int max_solves, const DataSpan& span,
                     const MomentWeights& weights) {
  std::vector<std::pair<double, size_t>> ranked;
  for (size_t i = 0; i < starts.size(); ++i) ranked.push_back({model_cost(points, structure, starts[i], weights), i});
  std::sort(ranked.begin(), ranked.end());
  SolveOutcome best;
  best.cost = kInfinity;
  const size_t solves = std::min(ranked.size(), static_cast<size_t>(max_solves));
  for (size_t r = 0; r < solves; ++r) {
    if (!std::isfinite(ranked[r].first)) continue;
    SolveOutcome outcome = solve_model(points, structure, starts[ranked[r].second], span, weights);
    if (outcome.usable && outcome.cost < best.cost) best = outcome;
  }
  return best;
}

bool is_extra_term(TermKind kind) {
  return kind == TermKind::kMarkov || kind == TermKind::kSinusoid || kind == TermKind::kZeroDcFamily ||
         kind == TermKind::kResonance || kind == TermKind::kZeroDcGaussian || kind == TermKind::kHighPassWhite;
}

struct SelectionContext {
  const std::vector<FitPoint>& points;
  const DataSpan& span;
  const FitOptions& options;
  OavarCovariance& covariance;
  double discrepancy;
  int point_count;
};

// The current model under weights of its own: the weights follow the model and the model the
// weights until the model's AVAR at every point moves by less than 5 % (iterated GMM).
void reweigh(const SelectionContext& context, SelectedModel* current) {
  constexpr int kMaxIterations = 4;
  constexpr double kSettled = 0.05;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const NoiseModel model = model_from_log_parameters(current->structure, current->log_parameters);
    current->weights = moment_weights(context.points, model, context.covariance, context.discrepancy);
    const SolveOutcome refit =
        refit_structure(context.points, current->structure, current->log_parameters, context.span, current->weights);
    if (!refit.usable) break;
    const NoiseModel refitted = model_from_log_parameters(current->structure, refit.log_parameters);
    double largest_change = 0.0;
    for (const FitPoint& point : context.points) {
      largest_change =
          std::max(largest_change, std::abs(model_avar(refitted, point.tau_s) / model_avar(model, point.tau_s) - 1.0));
    }
    current->log_parameters = refit.log_parameters;
    if (largest_change < kSettled) break;
  }
  current->cost = model_cost(context.points, current->structure, current->log_parameters, current->weights);
}

// A term driven to a negligible amplitude has no gradient left and stays there (a local
// optimum the next step inherits). Restart each term in turn from fractions of its envelope.
SolveOutcome polish(const SelectionContext& context, const ModelStructure& structure, const SolveOutcome& fitted,
                    const MomentWeights& weights) {
  SolveOutcome best = fitted;
  const NoiseModel model = model_from_log_parameters(structure, fitted.log_parameters);
  std::vector<std::vector<double>> starts;
  for (size_t i = 0; i < structure.slots.size(); ++i) {
    const double envelope = envelope_amplitude(model.terms[i], context.points);
    if (!(envelope > 0.0) || !std::isfinite(envelope)) continue;
    for (double fraction : {0.3, 0.1}) {
      std::vector<double> start = fitted.log_parameters;
      start[parameter_offset(structure, static_cast<int>(i))] = std::log(fraction * envelope);
      starts.push_back(start);
    }
  }
  const SolveOutcome restarted =
      best_of(context.points, structure, starts, static_cast<int>(starts.size()), context.span, weights);
  if (restarted.usable && restarted.cost < best.cost - 1e-9) best = restarted;
  return best;
}

struct Addition {
  SolveOutcome outcome;  // cost infinity when no candidate could be fitted
  ModelStructure structure;
  size_t index = 0;  // into the candidate list
};

// The candidate whose addition to `base` fits best (extra terms only if allowed).
Addition best_addition(const SelectionContext& context, const ModelStructure& base,
                       const std::vector<double>& base_parameters, const std::vector<TermSlot>& candidates,
                       bool allow_extras, const MomentWeights& weights) {
  Addition best;
  best.outcome.cost = kInfinity;
  double best_score = kInfinity;
  for (size_t c = 0; c < candidates.size(); ++c) {
    if (is_extra_term(candidates[c].kind) && !allow_extras) continue;
    // The numbered kinds (two Markov terms, two sinusoids...) are identical slots: the same fit,
    // and the first of equal scores wins anyway.
    const auto same_slot = [&](const TermSlot& earlier) {
      return earlier.kind == candidates[c].kind && earlier.shape_free == candidates[c].shape_free &&
             earlier.fixed_shape == candidates[c].fixed_shape;
    };
    if (std::any_of(candidates.begin(), candidates.begin() + c, same_slot)) continue;
    ModelStructure extended;
    const SolveOutcome outcome = fit_with_new_slot(context.points, context.span, context.options, base, base_parameters,
                                                   candidates[c], weights, &extended);
    if (!outcome.usable) continue;
    // The distance left plus half the candidate's threshold: among candidates of different
    // parameter counts (a sinusoid or a resonance for one peak) the one whose fall of J clears
    // its own threshold by most wins.
    const double score = outcome.cost + 0.5 * slot_lr_threshold(context.options, candidates[c], context.point_count);
    if (score < best_score) {
      best_score = score;
      best.outcome = outcome;
      best.structure = extended;
      best.index = c;
    }
  }
  return best;
}

// The weights change with the model: every comparison is made under the current model's (the
// null hypothesis's) weights, scaled to the measured curve (moment_weights).
void accept(const SelectionContext& context, const ModelStructure& structure, const SolveOutcome& outcome,
            SelectedModel* current) {
  current->structure = structure;
  current->log_parameters = outcome.log_parameters;
  reweigh(context, current);
}

// Forward, in two tiers: the standards' power-law terms first (the hypothesis a reader expects),
// then Markov, sinusoid, resonance and zero-DC terms when the data still ask for them. A flexible
// term admitted first would otherwise absorb a mixture of simple terms and block them.
bool front_end_pass(const SelectionContext& context, SelectedModel* current);

// An extension judged as the backward pass will judge it, so that a term added is not dropped
// again at once: under the extended model's own weights, the rise of J when the current
// structure is refitted there.
struct Extension {
  SelectedModel model;
  double statistic = 0.0;
};

Extension weigh_extension(const SelectionContext& context, const SelectedModel& current,
                          const ModelStructure& structure, const SolveOutcome& outcome) {
  Extension extension;
  extension.model = current;
  extension.model.structure = structure;
  extension.model.log_parameters = outcome.log_parameters;
  reweigh(context, &extension.model);
  const SolveOutcome reduced =
      refit_structure(context.points, current.structure, current.log_parameters, context.span, extension.model.weights);
  extension.statistic = reduced.usable ? 2.0 * (reduced.cost - extension.model.cost) : kInfinity;
  return extension;
}

// True if the extension is significant both under the current weights (a cheap screen) and under
// its own; then it becomes the current model with `step` recorded.
bool try_extension(const SelectionContext& context, const ModelStructure& structure, const SolveOutcome& outcome,
                   const TermSlot& slot, SelectionStep step, SelectedModel* current) {
  step.threshold = slot_lr_threshold(context.options, slot, context.point_count);
  if (!(2.0 * (current->cost - outcome.cost) > step.threshold)) return false;
  Extension extension = weigh_extension(context, *current, structure, outcome);
  step.lr_statistic = extension.statistic;
  if (!(extension.statistic > step.threshold)) return false;
  *current = std::move(extension.model);
  current->steps.push_back(step);
  return true;
}

void forward_pass(const SelectionContext& context, std::vector<TermSlot>* remaining, SelectedModel* current) {
  // Until a whole pass adds nothing: a peak or hump modelled in the second tier can reveal a
  // standard term the first could not see behind it.
  bool added_any = true;
  while (added_any) {
    added_any = false;
    for (bool extras : {false, true}) {
      // The front end belongs to the white noise: decided before a Markov term can stand in.
      if (extras) added_any |= front_end_pass(context, current);
      while (true) {
        const Addition addition =
            best_addition(context, current->structure, current->log_parameters, *remaining, extras, current->weights);
        if (!std::isfinite(addition.outcome.cost)) break;
        const SolveOutcome best = polish(context, addition.structure, addition.outcome, current->weights);
        const TermSlot added = (*remaining)[addition.index];
        if (current->structure.slots.empty()) {
          current->steps.push_back({"start", term_kind_name(added.kind), 0.0, 0.0});
          accept(context, addition.structure, best, current);
        } else if (!try_extension(context, addition.structure, best, added,
                                  {"add", term_kind_name(added.kind), 0.0, 0.0}, current)) {
          break;
        }
        remaining->erase(remaining->begin() + addition.index);
        added_any = true;
        // A peak or hump just modelled may have been hiding the front end's roll-off.
        if (extras) front_end_pass(context, current);
      }
    }
  }
}

// The white rate noise seen through a first-order front end (its corner fitted), if that lowers
// J significantly: the anti-alias filter that pulls the leftmost points down.
bool front_end_pass(const SelectionContext& context, SelectedModel* current) {
  if (!context.options.allow_front_end || context.options.front_end_corner_hz > 0.0) return false;
  for (size_t i = 0; i < current->structure.slots.size(); ++i) {
    const TermSlot& slot = current->structure.slots[i];
    if (slot.kind != TermKind::kWhiteRate || slot.shape_free) continue;
    ModelStructure upgraded = current->structure;
    upgraded.slots[i].shape_free = true;
    const int offset = parameter_offset(current->structure, static_cast<int>(i));
    std::vector<std::vector<double>> starts;
    for (const Term& shape : start_shapes(upgraded.slots[i], context.points, context.span)) {
      std::vector<double> start = current->log_parameters;
      start.insert(start.begin() + offset + 1, std::log(shape.shape));
      starts.push_back(start);
    }
    const SolveOutcome outcome =
        best_of(context.points, upgraded, starts, static_cast<int>(starts.size()), context.span, current->weights);
    if (!outcome.usable) return false;
    return try_extension(context, upgraded, outcome, upgraded.slots[i],
                         {"front end", term_kind_name(slot.kind), 0.0, 0.0}, current);
  }
  return false;
}

// Backward: drop the least significant term (never the white rate noise) while its removal is
// not significant; the dropped slots go back to `remaining`. True if any was dropped.
bool backward_pass(const SelectionContext& context, std::vector<TermSlot>* remaining, SelectedModel* current) {
  bool removed_any = false;
  while (current->structure.slots.size() > 1) {
    const int slot_count = static_cast<int>(current->structure.slots.size());
    double worst_margin = kInfinity;
    int worst_slot = -1;
    double worst_statistic = 0.0;
    SolveOutcome worst_outcome;
    ModelStructure worst_structure;
    for (int i = 0; i < slot_count; ++i) {
      // White rate noise is every sensor's floor: a Markov term or a peak may not stand in for it
      // (its front end does that job).
      if (current->structure.slots[i].kind == TermKind::kWhiteRate) continue;
      ModelStructure reduced = current->structure;
      std::vector<double> reduced_parameters = current->log_parameters;
      remove_slot(reduced, reduced_parameters, i);
      const SolveOutcome outcome =
          refit_structure(context.points, reduced, reduced_parameters, context.span, current->weights);
      if (!outcome.usable) continue;
      const double statistic = 2.0 * (outcome.cost - current->cost);
      const double margin =
          statistic - slot_lr_threshold(context.options, current->structure.slots[i], context.point_count);
      if (margin < worst_margin) {
        worst_margin = margin;
        worst_slot = i;
        worst_statistic = statistic;
        worst_outcome = outcome;
        worst_structure = reduced;
      }
    }
    if (worst_slot < 0 || worst_margin >= 0.0) break;
    const TermSlot removed = current->structure.slots[worst_slot];
    current->steps.push_back({"remove", term_kind_name(removed.kind), worst_statistic,
                              slot_lr_threshold(context.options, removed, context.point_count)});
    remaining->push_back(removed);
    accept(context, worst_structure, worst_outcome, current);
    removed_any = true;
  }
  return removed_any;
}

// Swap: an extra term stays only if no absent standard term does its job nearly as well (within
// its own threshold): the standard term is the reading a user expects.
bool swap_pass(const SelectionContext& context, std::vector<TermSlot>* remaining, SelectedModel* current) {
  for (size_t i = 0; i < current->structure.slots.size(); ++i) {
    const TermSlot extra = current->structure.slots[i];
    if (!is_extra_term(extra.kind)) continue;
    ModelStructure reduced = current->structure;
    std::vector<double> reduced_parameters = current->log_parameters;
    remove_slot(reduced, reduced_parameters, static_cast<int>(i));
    const Addition addition = best_addition(context, reduced, reduced_parameters, *remaining, false, current->weights);
    if (!std::isfinite(addition.outcome.cost)) continue;
    const double statistic = 2.0 * (addition.outcome.cost - current->cost);
    const double threshold = slot_lr_threshold(context.options, extra, context.point_count);
    if (!(statistic < threshold)) continue;
    // The standard term must earn its place in the swapped structure. Where it does not, the swap
    // is the extra term's removal at a rise of J its threshold does not allow (the backward pass
    // would keep it): the standard term is then dropped, the extra term added again, and the
    // passes cycle until the round limit, leaving whichever came last.
    const TermSlot& standard = (*remaining)[addition.index];
    const SolveOutcome without_both =
        refit_structure(context.points, reduced, reduced_parameters, context.span, current->weights);
    if (without_both.usable && 2.0 * (without_both.cost - addition.outcome.cost) <
                                   slot_lr_threshold(context.options, standard, context.point_count)) {
      continue;
    }
    current->steps.push_back(
        {"swap " + term_kind_name(extra.kind) + " for", term_kind_name(standard.kind), statistic, threshold});
    remaining->erase(remaining->begin() + addition.index);
    remaining->push_back(extra);
    accept(context, addition.structure, addition.outcome, current);
    return true;
  }
  return false;
}

// Each slot's removal statistic in the final model, under its final weights.
void removal_statistics(const SelectionContext& context, SelectedModel* current) {
  const int slot_count = static_cast<int>(current->structure.slots.size());
  current->removal_lr_statistics.assign(slot_count, kInfinity);
  current->removal_thresholds.assign(slot_count, 0.0);
  for (int i = 0; i < slot_count; ++i) {
    current->removal_thresholds[i] =
        slot_lr_threshold(context.options, current->structure.slots[i], context.point_count);
    if (slot_count == 1) continue;
    ModelStructure reduced = current->structure;
    std::vector<double> reduced_parameters = current->log_parameters;
    remove_slot(reduced, reduced_parameters, i);
    const SolveOutcome outcome =
        refit_structure(context.points, reduced, reduced_parameters, context.span, current->weights);
    if (outcome.usable) current->removal_lr_statistics[i] = 2.0 * (outcome.cost - current->cost);
  }
}

}  // namespace

bool is_borderline(double statistic, double threshold, bool in_model) {
  if (!std::isfinite(statistic)) return false;
  return in_model ? statistic < 2.0 * threshold : statistic > 0.5 * threshold;
}

std::vector<TermSlot> candidate_slots(const FitOptions& options, const DataSpan& span) {
  std::vector<TermSlot> slots;
  const auto add = [&](bool allowed, TermKind kind) {
    if (allowed) slots.push_back({kind, has_shape(kind), 0.0});
  };
  add(options.allow_white_angle, TermKind::kWhiteAngle);
  if (options.allow_white_rate) {
    // Plain white noise first; the front end is a step of its own (front_end_pass), unless its
    // corner is known.
    slots.push_back({TermKind::kWhiteRate, false, options.front_end_corner_hz});
  }
  if (options.allow_bias_instability) {
    TermSlot bias{TermKind::kBiasInstability, options.bias_cutoff == BiasCutoff::kFitted, 0.0};
    bias.fixed_shape = options.bias_cutoff == BiasCutoff::kGiven ? options.bias_cutoff_hz : 1.0 / (2.0 * span.tau0_s);
    slots.push_back(bias);
  }
  add(options.allow_random_walk, TermKind::kRandomWalk);
  add(options.allow_rate_ramp, TermKind::kRateRamp);
  for (int i = 0; i < options.max_markov_terms; ++i) add(true, TermKind::kMarkov);
  for (int i = 0; i < options.max_sinusoids; ++i) add(true, TermKind::kSinusoid);
  for (int i = 0; i < options.max_resonances; ++i) add(true, TermKind::kResonance);
  add(options.allow_zero_dc_family, TermKind::kZeroDcFamily);
  add(options.allow_zero_dc_gaussian, TermKind::kZeroDcGaussian);
  add(options.allow_high_pass_white, TermKind::kHighPassWhite);
  return slots;
}

double slot_lr_threshold(const FitOptions& options, const TermSlot& slot, int point_count) {
  const double trials = slot.shape_free ? std::max(1, point_count) : 1.0;
  return chi_squared_quantile(1.0 - options.significance / trials, slot_parameter_count(slot));
}

SolveOutcome fit_with_new_slot(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                               const ModelStructure& base, const std::vector<double>& base_parameters,
                               const TermSlot& slot, const MomentWeights& weights, ModelStructure* extended) {
  *extended = base;
  extended->slots.push_back(slot);
  std::vector<std::vector<double>> starts;
  for (const auto& slot_start : new_slot_starts(slot, points, span, options.envelope_fractions)) {
    for (double base_factor : {1.0, 0.5}) {
      if (base.slots.empty() && base_factor != 1.0) continue;
      std::vector<double> start = scaled_amplitudes(base, base_parameters, base_factor);
      start.insert(start.end(), slot_start.begin(), slot_start.end());
      starts.push_back(start);
    }
  }
  return best_of(points, *extended, starts, options.solves_per_candidate, span, weights);
}

SolveOutcome refit_structure(const std::vector<FitPoint>& points, const ModelStructure& structure,
                             const std::vector<double>& start, const DataSpan& span, const MomentWeights& weights) {
  std::vector<std::vector<double>> starts;
  for (double factor : {1.0, 0.7, 1.4}) starts.push_back(scaled_amplitudes(structure, start, factor));
  return best_of(points, structure, starts, static_cast<int>(starts.size()), span, weights);
}

int term_claiming_more_than_the_curve(const std::vector<FitPoint>& points, const NoiseModel& model,
                                      const MomentWeights& weights) {
  for (size_t k = 0; k < points.size(); ++k) {
    const double upper = band_limits(std::sqrt(points[k].avar), weights.edf(k)).upper;
    for (size_t i = 0; i < model.terms.size(); ++i) {
      const Term& term = model.terms[i];
      const bool grows_with_tau = term.kind == TermKind::kRandomWalk || term.kind == TermKind::kRateRamp;
      if (grows_with_tau && term_avar(term, points[k].tau_s) > upper * upper) {
        return static_cast<int>(i);
      }
    }
  }
  return -1;
}

SelectedModel select_model(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                           OavarCovariance& covariance, double discrepancy, const NoiseModel& first_weight_model,
                           const SelectedModel* start) {
  const SelectionContext context{points, span, options, covariance, discrepancy, static_cast<int>(points.size())};
  std::vector<TermSlot> remaining = candidate_slots(options, span);
  SelectedModel current;
  current.structure.output_quantization_density = first_weight_model.output_quantization_density;
  current.cost = kInfinity;
  current.weights = moment_weights(points, first_weight_model, covariance, discrepancy);
  if (start != nullptr) {
    current.structure = start->structure;
    current.log_parameters = start->log_parameters;
    current.steps = start->steps;
    for (const TermSlot& used : current.structure.slots) {
      const auto match = std::find_if(remaining.begin(), remaining.end(),
                                      [&](const TermSlot& slot) { return slot.kind == used.kind; });
      if (match != remaining.end()) remaining.erase(match);
    }
    reweigh(context, &current);
  }
  // Greedy forward selection depends on the order terms enter; after a removal or swap, search
  // again.
  constexpr int kMaxRounds = 3;
  for (int round = 0; round < kMaxRounds; ++round) {
    forward_pass(context, &remaining, &current);
    const bool removed = backward_pass(context, &remaining, &current);
    const bool swapped = swap_pass(context, &remaining, &current);
    if (swapped) backward_pass(context, &remaining, &current);
    if (!removed && !swapped) break;
  }
  canonical_order(current.structure, current.log_parameters);
  removal_statistics(context, &current);
  return current;
}

void refit_selected(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                    OavarCovariance& covariance, double discrepancy, SelectedModel* selected) {
  const SelectionContext context{points, span, options, covariance, discrepancy, static_cast<int>(points.size())};
  reweigh(context, selected);
  removal_statistics(context, selected);
}

void reweigh_selected(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                      OavarCovariance& covariance, double discrepancy, SelectedModel* selected) {
  const SelectionContext context{points, span, options, covariance, discrepancy, static_cast<int>(points.size())};
  reweigh(context, selected);
}

}  // namespace identify
}  // namespace imu_lab
