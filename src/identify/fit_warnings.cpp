#include "imu_lab/identify/fit_warnings.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "imu_lab/identify/white_equivalent.h"

namespace imu_lab {
namespace identify {

namespace {

std::string format_number(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value;
  return out.str();
}

// The fitted value of a term, or its upper bound when it is not in the model.
double value_or_bound(const TermEstimate* term) {
  if (term == nullptr) return std::nan("");
  return term->status == TermStatus::kPresent ? term->amplitude.value : term->amplitude.upper_bound;
}

// Names of the model terms that contribute most of the AVAR at tau, other than `excluded`.
std::string dominant_terms_at(const FitResult& fit, double tau_s, TermKind excluded) {
  const double total = model_avar(fit.model, tau_s);
  std::string names;
  for (size_t i = 0; i < fit.model.terms.size(); ++i) {
    if (fit.model.terms[i].kind == excluded) continue;
    const double share = term_avar(fit.model.terms[i], tau_s) / total;
    if (share < 0.2) continue;
    if (!names.empty()) names += ", ";
    names += fit.terms[i].name + " (" + format_number(100.0 * share) + " % of AVAR)";
  }
  return names.empty() ? "no single other term" : names;
}

// A finding about `term` (its name and kind), the rest filled in by the caller.
FitFinding finding_about(FindingKind kind, const TermEstimate& term) {
  FitFinding finding;
  finding.kind = kind;
  finding.term = term.name;
  finding.term_kind = term.kind;
  return finding;
}

// A reading (slope or flat tangent) at tau set against the fitted term or its bound.
FitFinding reading_finding(FindingKind kind, const TermEstimate& term, double tau_s, double reading, double fitted) {
  FitFinding finding = finding_about(kind, term);
  finding.first_tau_s = tau_s;
  finding.value = reading;
  finding.fitted = fitted;
  finding.fitted_is_bound = term.status != TermStatus::kPresent;
  return finding;
}

// A slope reading (N at 1 s, K at 3 s) that disagrees with the fitted term or its bound.
void warn_slope_reading(const FitResult& fit, TermKind kind, double tau_s, double reading,
                        std::vector<FitFinding>* findings) {
  const TermEstimate* term = fit.find(term_kind_name(kind));
  const double fitted = value_or_bound(term);
  if (!std::isfinite(reading) || !std::isfinite(fitted) || !(reading > kReadingDisagreementRatio * fitted)) return;
  FitFinding finding = reading_finding(FindingKind::kSlopeReading, *term, tau_s, reading, fitted);
  const std::string symbol = amplitude_symbol(kind);
  finding.carriers = dominant_terms_at(fit, tau_s, kind);
  finding.text = "slope reading of " + symbol + " at tau = " + format_number(tau_s) + " s (" + format_number(reading) +
                 ") is " + format_number(reading / fitted) + "x the fitted " + symbol +
                 (finding.fitted_is_bound ? " upper bound" : "") + " (" + format_number(fitted) +
                 "): the curve there is carried by " + finding.carriers +
                 (finding.carriers.find("markov") != std::string::npos
                      ? " (a Markov flank posing as white noise, see doc/models.md)"
                      : "");
  findings->push_back(finding);
}

void warn_markov_as_white(const FitResult& fit, std::vector<FitFinding>* findings) {
  for (size_t i = 0; i < fit.model.terms.size(); ++i) {
    const Term& term = fit.model.terms[i];
    if (term.kind == TermKind::kMarkov && markov_acts_as_low_passed_white(term.shape, fit.points.front().tau_s)) {
      FitFinding finding = finding_about(FindingKind::kMarkovAsWhite, fit.terms[i]);
      finding.value = term.amplitude;
      finding.text = fit.terms[i].name + " has T_c = " + format_number(term.shape) +
                     " s, below twice the shortest tau: it behaves like low-passed white noise of density "
                     "q_c T_c = " +
                     format_number(term.amplitude) + "; kalibr_imu.yaml's noise density adds it to N in power";
      findings->push_back(finding);
    }
  }
}

void warn_bias_instability(const FitResult& fit, std::vector<FitFinding>* findings) {
  const double reading = fit.graphical.bias_instability_from_minimum;
  const TermEstimate* bias = fit.find("bias_instability");
  const double fitted = value_or_bound(bias);
  if (!std::isfinite(reading) || !std::isfinite(fitted)) return;
  if (reading > kReadingDisagreementRatio * fitted) {
    const double tau_s = fit.graphical.tau_at_minimum_s;
    FitFinding finding = reading_finding(FindingKind::kFlatTangentReading, *bias, tau_s, reading, fitted);
    finding.carriers = dominant_terms_at(fit, tau_s, TermKind::kBiasInstability);
    finding.text = "flat-tangent reading of B (minimum / 0.664 = " + format_number(reading) +
                   " at tau = " + format_number(tau_s) + " s) over-states the fitted B" +
                   (finding.fitted_is_bound ? " upper bound" : "") + " (" + format_number(fitted) + ") " +
                   format_number(reading / fitted) + "x: at the minimum the AVAR is mostly " + finding.carriers;
    findings->push_back(finding);
  }
}

// A term on the other side of its threshold from the decision was selected under a smaller
// spread than the one it is reported under (doc/identification.md, "Model discrepancy").
std::string borderline_warning(const TermEstimate& term, double discrepancy) {
  const bool in_model = term.status != TermStatus::kAbsent;
  const std::string statistic = format_number(term.selection_statistic);
  const std::string threshold = format_number(term.selection_threshold);
  std::string reason;
  if (in_model && term.selection_statistic < term.selection_threshold) {
    reason = "in the model, but under the weights reported its statistic " + statistic + " is below the threshold " +
             threshold;
    if (discrepancy > 0.0) {
      reason += " (it was selected under a smaller spread than the " + format_number(100.0 * discrepancy) +
                " % the model leaves)";
    }
  } else if (!in_model && term.selection_statistic > term.selection_threshold) {
    reason = "left out, but under the weights reported its statistic " + statistic + " exceeds the threshold " +
             threshold;
  } else {
    reason = "its selection statistic " + statistic + " is within a factor 2 of the threshold " + threshold;
  }
  return term.name + " is borderline: " + reason + "; another record may decide otherwise";
}

void warn_band(const FitResult& fit, std::vector<FitFinding>* findings) {
  for (const BandExcursion& excursion : band_excursions(fit.band)) {
    const bool single = excursion.point_count == 1;
    FitFinding finding;
    finding.kind = FindingKind::kBandExcursion;
    finding.first_tau_s = excursion.first_tau_s;
    finding.last_tau_s = excursion.last_tau_s;
    finding.value = excursion.largest_excursion;
    finding.text = "the fitted total leaves the measured curve's 95 % band at " +
                   (single ? "tau " + format_number(excursion.first_tau_s) + " s"
                           : "tau " + format_number(excursion.first_tau_s) + "-" + format_number(excursion.last_tau_s) +
                                 " s (" + std::to_string(excursion.point_count) + " points)") +
                   ", by up to " + format_number(100.0 * std::abs(excursion.largest_excursion)) +
                   " % of the deviation " + (excursion.largest_excursion > 0.0 ? "above" : "below") + " the band";
    findings->push_back(finding);
  }
  // A term whose own partial curve exceeds the band's upper bound claims more than the curve has.
  for (size_t i = 0; i < fit.model.terms.size(); ++i) {
    for (const BandPoint& point : fit.band) {
      if (std::sqrt(term_avar(fit.model.terms[i], point.tau_s)) > point.upper) {
        FitFinding finding = finding_about(FindingKind::kPartialAboveBand, fit.terms[i]);
        finding.first_tau_s = point.tau_s;
        finding.text = fit.terms[i].name + "'s own partial curve exceeds the band's upper bound at tau " +
                       format_number(point.tau_s) + " s: the data do not support its value there";
        findings->push_back(finding);
        break;
      }
    }
  }
}

// Every present parameter whose reported value lies outside its own 68.3 % interval, named
// "term parameter", comma-separated.
std::string values_outside_their_intervals(const FitResult& fit) {
  std::string names;
  for (const TermEstimate& term : fit.terms) {
    if (term.status != TermStatus::kPresent) continue;
    const std::pair<const char*, const ParameterEstimate*> parameters[] = {
        {"amplitude", &term.amplitude}, {"shape", &term.shape}, {"width", &term.width}};
    for (const auto& [label, estimate] : parameters) {
      if (!std::isfinite(estimate->value) || !std::isfinite(estimate->log_sigma)) continue;
      if (estimate->value >= estimate->interval_low(1.0) && estimate->value <= estimate->interval_high(1.0)) continue;
      names += (names.empty() ? "" : ", ") + term.name + " " + label;
    }
  }
  return names;
}

// An alternative structure with a larger Akaike weight than the selected one (a left-out term
// whose addition lowers J by more than 2 but less than the selection's threshold): the intervals,
// the weighed structures' quantiles, lean to its values and may leave reported ones out.
void warn_outweighed_selection(const FitResult& fit, std::vector<FitFinding>* findings) {
  double selected_weight = 1.0;
  for (const StructureAlternative& alternative : fit.structure_alternatives) selected_weight -= alternative.weight;
  const std::string outside = values_outside_their_intervals(fit);
  for (const StructureAlternative& alternative : fit.structure_alternatives) {
    if (!(alternative.weight > selected_weight)) continue;
    FitFinding finding;
    finding.kind = FindingKind::kOutweighedStructure;
    const bool added = alternative.replaced.empty();
    finding.term = added ? alternative.replacement : alternative.replaced;
    if (const TermEstimate* term = fit.find(finding.term)) finding.term_kind = term->kind;
    finding.alternative =
        added ? alternative.replacement + " added" : alternative.replaced + " as a " + alternative.replacement;
    finding.value = alternative.weight;
    const std::string structure = added ? "with " + alternative.replacement + " added"
                                        : "with " + alternative.replaced + " described as a " + alternative.replacement;
    finding.text = "the structure " + structure + " outweighs the selected one by Akaike's criterion (weight " +
                   format_number(alternative.weight) + " against " + format_number(selected_weight) + ", J lower by " +
                   format_number(-alternative.distance_change) + "): the intervals lean towards its values" +
                   (outside.empty() ? "" : "; outside their own 68 % interval: " + outside);
    findings->push_back(finding);
  }
}

}  // namespace

std::vector<BandExcursion> band_excursions(const std::vector<BandPoint>& band) {
  std::vector<BandExcursion> excursions;
  bool open = false;
  for (const BandPoint& point : band) {
    if (point.inside()) {
      open = false;
      continue;
    }
    const double excursion = point.fitted_deviation > point.upper
                                 ? (point.fitted_deviation - point.upper) / point.measured_deviation
                                 : -(point.lower - point.fitted_deviation) / point.measured_deviation;
    // A run is one-sided: where the total crosses the band between neighbours, a new one starts,
    // so that each range's warning says on which side it lies.
    if (!open || (excursion > 0.0) != (excursions.back().largest_excursion > 0.0)) {
      excursions.push_back({point.tau_s, point.tau_s, 0, excursion});
      open = true;
    }
    BandExcursion& current = excursions.back();
    current.last_tau_s = point.tau_s;
    ++current.point_count;
    if (std::abs(excursion) > std::abs(current.largest_excursion)) current.largest_excursion = excursion;
  }
  return excursions;
}

std::vector<FitFinding> fit_findings(const FitResult& fit) {
  std::vector<FitFinding> findings;
  warn_slope_reading(fit, TermKind::kWhiteRate, 1.0, fit.graphical.white_rate_at_1s, &findings);
  warn_markov_as_white(fit, &findings);
  warn_bias_instability(fit, &findings);
  warn_slope_reading(fit, TermKind::kRandomWalk, 3.0, fit.graphical.random_walk_at_3s, &findings);
  if (fit.quality.discrepancy > 0.0) {
    FitFinding finding;
    finding.kind = FindingKind::kDiscrepancy;
    finding.value = fit.quality.discrepancy;
    finding.text = "the model describes the curve to about " + format_number(100.0 * fit.quality.discrepancy) +
                   " % in AVAR, less well than the estimates' precision: that spread is added to every point, "
                   "and the sigmas include it (a front end or a process outside the model family)";
    findings.push_back(finding);
  }
  warn_band(fit, &findings);
  warn_outweighed_selection(fit, &findings);
  for (const TermEstimate& term : fit.terms) {
    if (term.status == TermStatus::kUnconstrained) {
      FitFinding finding = finding_about(FindingKind::kUnconstrained, term);
      finding.value = term.amplitude.upper_bound;
      finding.text = term.name + " is in the model but the data do not constrain it: report its upper bound " +
                     format_number(term.amplitude.upper_bound) + ", not its value";
      findings.push_back(finding);
    }
    if (term.borderline) {
      FitFinding finding = finding_about(FindingKind::kBorderline, term);
      finding.text = borderline_warning(term, fit.quality.discrepancy);
      findings.push_back(finding);
    }
  }
  return findings;
}

std::vector<std::string> fit_warnings(const std::vector<FitFinding>& findings) {
  std::vector<std::string> warnings;
  for (const FitFinding& finding : findings) warnings.push_back(finding.text);
  return warnings;
}

}  // namespace identify
}  // namespace imu_lab
