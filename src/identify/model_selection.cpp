#include "imu_lab/identify/model_selection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "imu_lab/identify/avar_likelihood.h"
#include "imu_lab/identify/start_values.h"

namespace imu_lab {
namespace identify {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The same parameters with every amplitude multiplied by `factor` (shapes untouched).
std::vector<double> scaled_amplitudes(const ModelStructure& structure,
                                      std::vector<double> log_parameters, double factor) {
  for (size_t i = 0; i < structure.slots.size(); ++i) {
    log_parameters[parameter_offset(structure, static_cast<int>(i))] += std::log(factor);
  }
  return log_parameters;
}

SolveOutcome best_of(const std::vector<FitPoint>& points, const ModelStructure& structure,
                     std::vector<std::vector<double>> starts, int max_solves,
                     const DataSpan& span, const SolverSettings& settings) {
  std::vector<std::pair<double, size_t>> ranked;
  for (size_t i = 0; i < starts.size(); ++i) {
    ranked.push_back({model_cost(points, structure, starts[i], settings), i});
  }
  std::sort(ranked.begin(), ranked.end());
  SolveOutcome best;
  best.cost = kInfinity;
  const size_t solves = std::min(ranked.size(), static_cast<size_t>(max_solves));
  for (size_t r = 0; r < solves; ++r) {
    if (!std::isfinite(ranked[r].first)) continue;
    SolveOutcome outcome =
        solve_model(points, structure, starts[ranked[r].second], span, settings);
    if (outcome.usable && outcome.cost < best.cost) best = outcome;
  }
  return best;
}

SolveOutcome fit_with_new_slot(const std::vector<FitPoint>& points, const ModelStructure& base,
                               const std::vector<double>& base_parameters, const TermSlot& slot,
                               const DataSpan& span, const FitOptions& options,
                               const SolverSettings& settings, ModelStructure* extended) {
  *extended = base;
  extended->slots.push_back(slot);
  std::vector<std::vector<double>> starts;
  const auto slot_starts = new_slot_starts(slot, points, span, base.white_rate_corner_hz,
                                           options.envelope_fractions);
  for (const auto& slot_start : slot_starts) {
    for (double base_factor : {1.0, 0.5}) {
      if (base.slots.empty() && base_factor != 1.0) continue;
      std::vector<double> start = scaled_amplitudes(base, base_parameters, base_factor);
      start.insert(start.end(), slot_start.begin(), slot_start.end());
      starts.push_back(start);
    }
  }
  return best_of(points, *extended, starts, options.solves_per_candidate, span, settings);
}

// A term driven to a negligible amplitude has no gradient left and stays there (a local
// optimum the next step inherits). Restart each term in turn from fractions of its envelope.
SolveOutcome polish(const std::vector<FitPoint>& points, const ModelStructure& structure,
                    const SolveOutcome& fitted, const DataSpan& span,
                    const SolverSettings& settings) {
  SolveOutcome best = fitted;
  const NoiseModel model = model_from_log_parameters(structure, fitted.log_parameters);
  std::vector<std::vector<double>> starts;
  for (size_t i = 0; i < structure.slots.size(); ++i) {
    const double envelope = envelope_amplitude(model.terms[i].kind, model.terms[i].shape, points,
                                               structure.white_rate_corner_hz);
    if (!(envelope > 0.0) || !std::isfinite(envelope)) continue;
    for (double fraction : {0.3, 0.1}) {
      std::vector<double> start = fitted.log_parameters;
      start[parameter_offset(structure, static_cast<int>(i))] = std::log(fraction * envelope);
      starts.push_back(start);
    }
  }
  const SolveOutcome restarted =
      best_of(points, structure, starts, static_cast<int>(starts.size()), span, settings);
  if (restarted.usable && restarted.cost < best.cost - 1e-9) best = restarted;
  return best;
}

bool is_extra_term(TermKind kind) {
  return kind == TermKind::kMarkov || kind == TermKind::kSinusoid ||
         kind == TermKind::kZeroDcFamily;
}

struct SelectionContext {
  const std::vector<FitPoint>& points;
  const DataSpan& span;
  const FitOptions& options;
  SolverSettings settings;
  int point_count;
};

struct Addition {
  SolveOutcome outcome;  // cost infinity when no candidate could be fitted
  ModelStructure structure;
  size_t index = 0;  // into the candidate list
};

// The candidate whose addition to `base` fits best (extra terms only if allowed).
Addition best_addition(const SelectionContext& context, const ModelStructure& base,
                       const std::vector<double>& base_parameters,
                       const std::vector<TermSlot>& candidates, bool allow_extras) {
  Addition best;
  best.outcome.cost = kInfinity;
  for (size_t c = 0; c < candidates.size(); ++c) {
    if (is_extra_term(candidates[c].kind) && !allow_extras) continue;
    ModelStructure extended;
    const SolveOutcome outcome =
        fit_with_new_slot(context.points, base, base_parameters, candidates[c], context.span,
                          context.options, context.settings, &extended);
    if (outcome.usable && outcome.cost < best.outcome.cost) {
      best.outcome = outcome;
      best.structure = extended;
      best.index = c;
    }
  }
  return best;
}

// Forward, in two tiers: the standards' power-law terms first (the hypothesis a reader
// expects), then Markov, sinusoid and zero-DC terms when the data still ask for them. A
// flexible two-parameter term admitted first would otherwise absorb a mixture of simple terms
// (a long Markov mimicking B + K) and block them.
void forward_pass(const SelectionContext& context, std::vector<TermSlot>* remaining,
                  SelectedModel* current) {
  for (bool extras : {false, true}) {
    while (true) {
      const Addition addition = best_addition(context, current->structure, current->log_parameters,
                                        *remaining, extras);
      if (!std::isfinite(addition.outcome.cost)) break;
      const SolveOutcome best = polish(context.points, addition.structure, addition.outcome,
                                       context.span, context.settings);
      const ModelStructure& best_structure = addition.structure;
      const size_t best_index = addition.index;
      const TermSlot& added = (*remaining)[best_index];
      SelectionStep step{current->structure.slots.empty() ? "start" : "add",
                         term_kind_name(added.kind), 0.0, 0.0};
      if (!current->structure.slots.empty()) {
        step.lr_statistic = 2.0 * (current->cost - best.cost);
        step.threshold = slot_lr_threshold(context.options, added, context.point_count);
        if (!(step.lr_statistic > step.threshold)) break;
      }
      current->steps.push_back(step);
      current->structure = best_structure;
      current->log_parameters = best.log_parameters;
      current->cost = best.cost;
      remaining->erase(remaining->begin() + best_index);
    }
  }
}

// Backward: drop the least significant term while its removal is not significant; the dropped
// slots go back to `remaining`. Leaves each kept slot's removal statistic; true if any dropped.
bool backward_pass(const SelectionContext& context, std::vector<TermSlot>* remaining,
                   SelectedModel* current) {
  bool removed_any = false;
  while (true) {
    const int slot_count = static_cast<int>(current->structure.slots.size());
    current->removal_lr_statistics.assign(slot_count, kInfinity);
    if (slot_count <= 1) break;
    double worst_margin = kInfinity;
    int worst_slot = -1;
    SolveOutcome worst_outcome;
    ModelStructure worst_structure;
    for (int i = 0; i < slot_count; ++i) {
      ModelStructure reduced = current->structure;
      std::vector<double> reduced_parameters = current->log_parameters;
      remove_slot(reduced, reduced_parameters, i);
      const SolveOutcome outcome = refit_structure(context.points, reduced, reduced_parameters,
                                                   context.span, context.settings);
      if (!outcome.usable) continue;
      const double lr = 2.0 * (outcome.cost - current->cost);
      current->removal_lr_statistics[i] = lr;
      const double margin = lr - slot_lr_threshold(context.options, current->structure.slots[i],
                                                   context.point_count);
      if (margin < worst_margin) {
        worst_margin = margin;
        worst_slot = i;
        worst_outcome = outcome;
        worst_structure = reduced;
      }
    }
    if (worst_slot < 0 || worst_margin >= 0.0) break;
    const TermSlot removed = current->structure.slots[worst_slot];
    current->steps.push_back(
        {"remove", term_kind_name(removed.kind), current->removal_lr_statistics[worst_slot],
         slot_lr_threshold(context.options, removed, context.point_count)});
    remaining->push_back(removed);
    current->structure = worst_structure;
    current->log_parameters = worst_outcome.log_parameters;
    current->cost = worst_outcome.cost;
    removed_any = true;
  }
  return removed_any;
}

// Swap: an extra term (Markov, sinusoid, zero-DC) stays only if no absent standard term does
// its job nearly as well (within its own threshold): a sinusoid near Nyquist can stand in for
// white noise on the first points, and the standard term is the reading a user expects.
bool swap_pass(const SelectionContext& context, std::vector<TermSlot>* remaining,
               SelectedModel* current) {
  for (size_t i = 0; i < current->structure.slots.size(); ++i) {
    const TermSlot extra = current->structure.slots[i];
    if (!is_extra_term(extra.kind)) continue;
    ModelStructure reduced = current->structure;
    std::vector<double> reduced_parameters = current->log_parameters;
    remove_slot(reduced, reduced_parameters, static_cast<int>(i));
    const Addition addition =
        best_addition(context, reduced, reduced_parameters, *remaining, false);
    const SolveOutcome& best = addition.outcome;
    const ModelStructure& best_structure = addition.structure;
    const size_t best_index = addition.index;
    const double lr = 2.0 * (best.cost - current->cost);
    const double threshold = slot_lr_threshold(context.options, extra, context.point_count);
    if (!(lr < threshold)) continue;
    current->steps.push_back({"swap " + term_kind_name(extra.kind) + " for",
                              term_kind_name((*remaining)[best_index].kind), lr, threshold});
    remaining->erase(remaining->begin() + best_index);
    remaining->push_back(extra);
    current->structure = best_structure;
    current->log_parameters = best.log_parameters;
    current->cost = best.cost;
    return true;
  }
  return false;
}

}  // namespace

std::vector<TermSlot> candidate_slots(const FitOptions& options, const DataSpan& span) {
  std::vector<TermSlot> slots;
  const auto add = [&](bool allowed, TermKind kind) {
    if (allowed) slots.push_back({kind, has_shape(kind), 0.0});
  };
  add(options.allow_white_angle, TermKind::kWhiteAngle);
  add(options.allow_white_rate, TermKind::kWhiteRate);
  if (options.allow_bias_instability) {
    TermSlot bias{TermKind::kBiasInstability, options.bias_cutoff == BiasCutoff::kFitted, 0.0};
    bias.fixed_shape = options.bias_cutoff == BiasCutoff::kGiven ? options.bias_cutoff_hz
                                                                 : 1.0 / (2.0 * span.tau0_s);
    slots.push_back(bias);
  }
  add(options.allow_random_walk, TermKind::kRandomWalk);
  add(options.allow_rate_ramp, TermKind::kRateRamp);
  for (int i = 0; i < options.max_markov_terms; ++i) add(true, TermKind::kMarkov);
  add(options.allow_sinusoid, TermKind::kSinusoid);
  add(options.allow_zero_dc_family, TermKind::kZeroDcFamily);
  return slots;
}

SolverSettings solver_settings(const FitOptions& options) {
  SolverSettings settings;
  settings.robust_loss_scale = options.robust_loss_scale;
  return settings;
}

double slot_lr_threshold(const FitOptions& options, const TermSlot& slot, int point_count) {
  const double trials = slot.shape_free ? std::max(1, point_count) : 1.0;
  return chi_squared_quantile(1.0 - options.significance / trials, slot_parameter_count(slot));
}

SolveOutcome refit_structure(const std::vector<FitPoint>& points, const ModelStructure& structure,
                             const std::vector<double>& start, const DataSpan& span,
                             const SolverSettings& settings) {
  std::vector<std::vector<double>> starts;
  for (double factor : {1.0, 0.7, 1.4}) starts.push_back(scaled_amplitudes(structure, start, factor));
  return best_of(points, structure, starts, static_cast<int>(starts.size()), span, settings);
}

SelectedModel select_model(const std::vector<FitPoint>& points, const DataSpan& span,
                           const FitOptions& options) {
  const SelectionContext context{points, span, options, solver_settings(options),
                                 static_cast<int>(points.size())};
  std::vector<TermSlot> remaining = candidate_slots(options, span);
  SelectedModel current;
  current.structure.white_rate_corner_hz = options.white_rate_corner_hz;
  current.cost = kInfinity;
  // Greedy forward selection depends on the order terms enter (a sinusoid admitted before a
  // second Markov can stand in for white noise); after a removal or swap, search again.
  constexpr int kMaxRounds = 3;
  for (int round = 0; round < kMaxRounds; ++round) {
    forward_pass(context, &remaining, &current);
    const bool removed = backward_pass(context, &remaining, &current);
    const bool swapped = swap_pass(context, &remaining, &current);
    if (swapped) backward_pass(context, &remaining, &current);
    if (!removed && !swapped) break;
  }

  // Canonical order, carrying the removal statistics along.
  NoiseModel tagged = model_from_log_parameters(current.structure, current.log_parameters);
  std::vector<std::pair<Term, double>> pairs;
  for (size_t i = 0; i < tagged.terms.size(); ++i) {
    pairs.push_back({tagged.terms[i], current.removal_lr_statistics[i]});
  }
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const auto& a, const auto& b) { return term_order_less(a.first, b.first); });
  canonical_order(current.structure, current.log_parameters);
  for (size_t i = 0; i < pairs.size(); ++i) current.removal_lr_statistics[i] = pairs[i].second;
  return current;
}

}  // namespace identify
}  // namespace imu_lab
