#include "imu_lab/identify/structure_doubt.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "imu_lab/identify/chi_squared.h"
#include "imu_lab/identify/model_selection.h"

namespace imu_lab {
namespace identify {

namespace {

// A line of peak Omega0 carries Omega0^2 / 2 of variance, a resonance of RMS r carries r^2.
const double kLineToRms = std::sqrt(0.5);
// Starts of the resonance's width / f_n when a line is swapped for one: from just above a line to
// a broad mode.
constexpr double kRelativeWidthStarts[] = {0.05, 0.15, 0.4};

struct FittedAlternative {
  StructureAlternative summary;
  int slot_index = 0;  // the swapped slot; for an addition, the appended one (past the selected slots)
  bool addition = false;
  ModelStructure structure;
  SolveOutcome outcome;
};

bool is_peak(const TermSlot& slot) {
  return slot.shape_free && (slot.kind == TermKind::kSinusoid || slot.kind == TermKind::kResonance);
}

// Whether every peak of the alternative still describes the selected structure's peak in its slot:
// the nearest (in ln f) of the selected peaks to each is its own. A refit may trade two peaks
// (the swapped one moving onto another line while that line takes its place); the parameters are
// then compared slot by slot with those of a different peak, and the alternative is not the
// same peak described by the other kind.
bool keeps_peak_identities(const ModelStructure& selected, const std::vector<double>& selected_log_parameters,
                           const ModelStructure& alternative, const std::vector<double>& alternative_log_parameters) {
  const auto log_frequency = [](const ModelStructure& structure, const std::vector<double>& log_parameters,
                                size_t slot) {
    return log_parameters[parameter_offset(structure, static_cast<int>(slot)) + 1];
  };
  for (size_t i = 0; i < alternative.slots.size(); ++i) {
    if (!is_peak(alternative.slots[i])) continue;
    const double own = log_frequency(alternative, alternative_log_parameters, i);
    const double own_distance = std::abs(own - log_frequency(selected, selected_log_parameters, i));
    for (size_t j = 0; j < selected.slots.size(); ++j) {
      if (j == i || !is_peak(selected.slots[j])) continue;
      if (std::abs(own - log_frequency(selected, selected_log_parameters, j)) < own_distance) return false;
    }
  }
  return true;
}

// The slot's peak described by the other kind, from starts at the same frequency and power. None
// when the other kind cannot sit at that frequency (a resonance's f_n lies in the top decade below
// the Nyquist frequency: fit_problem.h) or every refit trades peaks (keeps_peak_identities).
bool fit_alternative(const std::vector<FitPoint>& points, const DataSpan& span, const ModelStructure& structure,
                     const std::vector<double>& log_parameters, int slot_index, const MomentWeights& weights,
                     FittedAlternative* fitted) {
  const TermSlot& slot = structure.slots[slot_index];
  const int offset = parameter_offset(structure, slot_index);
  const double log_amplitude = log_parameters[offset];
  const double log_frequency = log_parameters[offset + 1];
  fitted->slot_index = slot_index;
  fitted->structure = structure;
  TermSlot& replacement = fitted->structure.slots[slot_index];
  replacement.shape_free = true;
  std::vector<std::vector<double>> peak_starts;
  if (slot.kind == TermKind::kSinusoid) {
    replacement.kind = TermKind::kResonance;
    for (double relative_width : kRelativeWidthStarts) {
      peak_starts.push_back({log_amplitude + std::log(kLineToRms), log_frequency, std::log(relative_width)});
    }
  } else {
    replacement.kind = TermKind::kSinusoid;
    peak_starts.push_back({log_amplitude - std::log(kLineToRms), log_frequency});
  }
  std::vector<double> lower, upper;
  log_parameter_bounds(fitted->structure, span, &lower, &upper);
  if (log_frequency < lower[offset + 1] || log_frequency > upper[offset + 1]) return false;
  fitted->outcome.cost = std::numeric_limits<double>::infinity();
  for (const std::vector<double>& peak : peak_starts) {
    std::vector<double> start(log_parameters.begin(), log_parameters.begin() + offset);
    start.insert(start.end(), peak.begin(), peak.end());
    start.insert(start.end(), log_parameters.begin() + offset + slot_parameter_count(slot), log_parameters.end());
    const SolveOutcome outcome = refit_structure(points, fitted->structure, start, span, weights);
    if (!outcome.usable || outcome.cost >= fitted->outcome.cost) continue;
    if (!keeps_peak_identities(structure, log_parameters, fitted->structure, outcome.log_parameters)) continue;
    fitted->outcome = outcome;
  }
  if (!fitted->outcome.usable) return false;
  fitted->summary.replacement = term_kind_name(replacement.kind);
  fitted->summary.peak_frequency_hz = std::exp(log_frequency);
  fitted->summary.parameter_change = slot_parameter_count(replacement) - slot_parameter_count(slot);
  return true;
}

// Index in the alternative's parameter vector of the selected structure's parameter p, or -1
// when p belongs to the replaced slot.
int shared_index(const ModelStructure& selected, const FittedAlternative& alternative, int p) {
  if (alternative.addition) return p;  // the added slot comes after every selected one
  const int begin = parameter_offset(selected, alternative.slot_index);
  const int end = begin + slot_parameter_count(selected.slots[alternative.slot_index]);
  if (p < begin) return p;
  if (p < end) return -1;
  return p + slot_parameter_count(alternative.structure.slots[alternative.slot_index]) - (end - begin);
}

// The alternative's own covariance of its log-parameters, for a swapped peak and an added Markov
// term (its correlation time trades with the floor beside it, which the offset alone misses). An
// added one-parameter term takes the selected structure's: it often sits at a negligible
// amplitude, where its own covariance is singular, and where it does not, its offset carries what
// it moves. So does a Markov term whose structure leaves any parameter loose (ln-sigma over
// FitOptions::unconstrained_relative_sigma): a hump that takes a floor's whole share leaves the
// floor unconstrained there, and its weight, however small, would swell the floor's mean-square
// sigma (doc/identification.md, "Doubt").
Eigen::MatrixXd alternative_covariance(const std::vector<FitPoint>& points, const FittedAlternative& alternative,
                                       const MomentWeights& weights, const FitOptions& options,
                                       const Eigen::MatrixXd& selected_covariance) {
  const bool added = alternative.addition;
  if (added && alternative.structure.slots.back().kind != TermKind::kMarkov) return selected_covariance;
  const Eigen::MatrixXd own =
      log_parameter_covariance(points, alternative.structure, alternative.outcome.log_parameters, weights);
  if (!added) return own;
  const double loosest = options.unconstrained_relative_sigma;
  return own.allFinite() && own.diagonal().maxCoeff() <= loosest * loosest ? own : selected_covariance;
}

}  // namespace

std::vector<StructureAlternative> weigh_structure_alternatives(const std::vector<FitPoint>& points,
                                                               const DataSpan& span, const FitOptions& options,
                                                               const ModelStructure& structure,
                                                               const std::vector<double>& log_parameters, double cost,
                                                               const MomentWeights& weights,
                                                               const std::vector<TermAddition>& additions,
                                                               Eigen::MatrixXd* log_covariance) {
  const std::vector<std::string> names = term_names(model_from_log_parameters(structure, log_parameters));
  std::vector<FittedAlternative> alternatives;
  for (size_t i = 0; i < structure.slots.size(); ++i) {
    const TermKind kind = structure.slots[i].kind;
    const bool line_to_mode = kind == TermKind::kSinusoid && options.max_resonances > 0;
    const bool mode_to_line = kind == TermKind::kResonance && options.max_sinusoids > 0;
    if (!line_to_mode && !mode_to_line) continue;
    FittedAlternative fitted;
    if (!fit_alternative(points, span, structure, log_parameters, static_cast<int>(i), weights, &fitted)) continue;
    fitted.summary.replaced = names[i];
    // Both costs are J / 2 under the same weights.
    fitted.summary.distance_change = 2.0 * (fitted.outcome.cost - cost);
    alternatives.push_back(fitted);
  }
  for (const TermAddition& addition : additions) {
    if (!addition.outcome.usable) continue;
    FittedAlternative fitted;
    fitted.addition = true;
    fitted.slot_index = static_cast<int>(structure.slots.size());
    fitted.structure = addition.structure;
    fitted.outcome = addition.outcome;
    fitted.summary.replacement = term_kind_name(addition.kind);
    fitted.summary.peak_frequency_hz = std::numeric_limits<double>::quiet_NaN();
    fitted.summary.distance_change = 2.0 * (addition.outcome.cost - cost);
    fitted.summary.parameter_change = parameter_count(addition.structure) - parameter_count(structure);
    alternatives.push_back(fitted);
  }
  if (alternatives.empty()) return {};

  // Akaike weights, relative to the selected structure (criterion difference 0). An added term
  // whose shape was searched (a Markov term's T_c over one start per point) is charged 2 ln(points)
  // more: the best of m chi-squared falls exceeds a single one by about 2 ln m, and with 2 per
  // parameter alone a Markov term that lowers J by chance would take a fair weight on every curve
  // (doc/identification.md, "Doubt").
  const auto criterion_change = [&](const FittedAlternative& alternative) {
    const bool searched = alternative.addition && alternative.structure.slots.back().shape_free;
    return alternative.summary.distance_change + 2.0 * alternative.summary.parameter_change +
           (searched ? 2.0 * std::log(std::max<double>(1.0, static_cast<double>(points.size()))) : 0.0);
  };
  double total = 1.0;
  for (const FittedAlternative& alternative : alternatives) total += std::exp(-0.5 * criterion_change(alternative));
  for (FittedAlternative& alternative : alternatives) {
    alternative.summary.weight = std::exp(-0.5 * criterion_change(alternative)) / total;
  }

  // Each structure's covariance of the selected parameters about the reported values: the
  // alternative's own covariance (alternative_covariance) and its offset where it shares a
  // parameter; the selected covariance for the replaced slot (the alternative says nothing of it),
  // uncorrelated with the rest.
  const Eigen::MatrixXd selected_covariance = *log_covariance;
  const int count = static_cast<int>(selected_covariance.rows());
  Eigen::MatrixXd widened = selected_covariance / total;
  for (FittedAlternative& alternative : alternatives) {
    alternative.summary.log_parameter_offsets.assign(count, 0.0);
    alternative.summary.log_covariance = Eigen::MatrixXd::Zero(count, count);
    const Eigen::MatrixXd covariance =
        alternative_covariance(points, alternative, weights, options, selected_covariance);
    for (int p = 0; p < count; ++p) {
      const int ap = shared_index(structure, alternative, p);
      alternative.summary.log_parameter_offsets[p] =
          ap < 0 ? 0.0 : alternative.outcome.log_parameters[ap] - log_parameters[p];
    }
    const std::vector<double>& offsets = alternative.summary.log_parameter_offsets;
    for (int p = 0; p < count; ++p) {
      const int ap = shared_index(structure, alternative, p);
      for (int q = 0; q < count; ++q) {
        const int aq = shared_index(structure, alternative, q);
        double own = 0.0;
        if (ap >= 0 && aq >= 0) {
          own = covariance(ap, aq);
        } else if (ap < 0 && aq < 0) {
          own = selected_covariance(p, q);
        }
        alternative.summary.log_covariance(p, q) = own;
        widened(p, q) += alternative.summary.weight * (own + offsets[p] * offsets[q]);
      }
    }
  }
  *log_covariance = widened;
  std::vector<StructureAlternative> summaries;
  for (const FittedAlternative& alternative : alternatives) summaries.push_back(alternative.summary);
  return summaries;
}

std::vector<LogNormalComponent> structure_mixture(const std::vector<StructureAlternative>& alternatives,
                                                  const Eigen::MatrixXd& selected_log_covariance,
                                                  const Eigen::VectorXd& combination) {
  const auto sigma_under = [&](const Eigen::MatrixXd& covariance) {
    return std::sqrt(std::max(0.0, combination.dot(covariance * combination)));
  };
  std::vector<LogNormalComponent> components(1);
  for (const StructureAlternative& alternative : alternatives) {
    const Eigen::Map<const Eigen::VectorXd> offsets(alternative.log_parameter_offsets.data(),
                                                    static_cast<Eigen::Index>(alternative.log_parameter_offsets.size()));
    components.push_back({alternative.weight, combination.dot(offsets), sigma_under(alternative.log_covariance)});
    components.front().weight -= alternative.weight;
  }
  components.front().log_sigma = sigma_under(selected_log_covariance);
  return components;
}

double mixture_log_quantile(const std::vector<LogNormalComponent>& components, double probability) {
  if (components.empty()) return 0.0;
  double total = 0.0, low = std::numeric_limits<double>::infinity(), high = -low;
  for (const LogNormalComponent& component : components) {
    total += component.weight;
    low = std::min(low, component.log_offset - 10.0 * component.log_sigma);
    high = std::max(high, component.log_offset + 10.0 * component.log_sigma);
  }
  const auto below = [&](double log_value) {
    double mass = 0.0;
    for (const LogNormalComponent& component : components) {
      const double standardized = component.log_sigma > 0.0
                                      ? (log_value - component.log_offset) / component.log_sigma
                                      : (log_value >= component.log_offset ? 1e300 : -1e300);
      mass += component.weight * 0.5 * std::erfc(-standardized / std::sqrt(2.0));
    }
    return mass / total;
  };
  // The mixture's distribution function rises monotonically from ~0 at `low` to ~1 at `high`.
  for (int iteration = 0; iteration < 200 && high - low > 1e-12 * (1.0 + std::abs(high)); ++iteration) {
    const double middle = 0.5 * (low + high);
    (below(middle) < probability ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

namespace {

// Each peak of `selected` of one kind refitted as the other (fit_alternative) under the current
// weights and swapped where the change of J passes: to modes, where J falls by more than one
// parameter's chi2 quantile (nested); to lines, where J does not rise (dominance). Reweighed after
// each swap; returns whether any was made.
bool swap_peak_kinds(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                     OavarCovariance& covariance, double discrepancy, bool lines_to_modes, SelectedModel* selected) {
  const TermKind from = lines_to_modes ? TermKind::kSinusoid : TermKind::kResonance;
  const TermKind to = lines_to_modes ? TermKind::kResonance : TermKind::kSinusoid;
  const int room = lines_to_modes ? options.max_resonances : options.max_sinusoids;
  const double threshold = lines_to_modes ? chi_squared_quantile(1.0 - options.significance, 1) : 0.0;
  int taken = 0;
  for (const TermSlot& slot : selected->structure.slots) taken += slot.kind == to;
  bool swapped = false;
  for (size_t i = 0; i < selected->structure.slots.size() && taken < room; ++i) {
    if (selected->structure.slots[i].kind != from) continue;
    FittedAlternative other;
    if (!fit_alternative(points, span, selected->structure, selected->log_parameters, static_cast<int>(i),
                         selected->weights, &other)) {
      continue;
    }
    // The fall of J for a mode (which must exceed the threshold), its rise for a line (which
    // must not).
    const double change = 2.0 * (other.outcome.cost - selected->cost);
    const double statistic = lines_to_modes ? -change : change;
    if (lines_to_modes ? !(statistic > threshold) : !(statistic <= threshold)) continue;
    selected->steps.push_back({"swap " + term_kind_name(from) + " for", term_kind_name(to), statistic, threshold});
    selected->structure = other.structure;
    selected->log_parameters = other.outcome.log_parameters;
    reweigh_selected(points, span, options, covariance, discrepancy, selected);
    ++taken;
    swapped = true;
  }
  if (swapped) canonical_order(selected->structure, selected->log_parameters);
  return swapped;
}

}  // namespace

bool swap_lines_for_modes(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                          OavarCovariance& covariance, double discrepancy, SelectedModel* selected) {
  return swap_peak_kinds(points, span, options, covariance, discrepancy, true, selected);
}

void swap_dominated_modes_for_lines(const std::vector<FitPoint>& points, const DataSpan& span,
                                    const FitOptions& options, OavarCovariance& covariance, double discrepancy,
                                    SelectedModel* selected) {
  if (swap_peak_kinds(points, span, options, covariance, discrepancy, false, selected)) {
    refit_selected(points, span, options, covariance, discrepancy, selected);
  }
}

}  // namespace identify
}  // namespace imu_lab
