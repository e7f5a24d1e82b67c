#include "imu_lab/identify/fit_warnings.h"

#include <cmath>
#include <sstream>

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
    const double share =
        term_avar(fit.model.terms[i], tau_s, fit.model.white_rate_corner_hz) / total;
    if (share < 0.2) continue;
    if (!names.empty()) names += ", ";
    names += fit.terms[i].name + " (" + format_number(100.0 * share) + " % of AVAR)";
  }
  return names.empty() ? "no single other term" : names;
}

// A slope reading (N at 1 s, K at 3 s) that disagrees with the fitted term or its bound.
void warn_slope_reading(const FitResult& fit, TermKind kind, double tau_s, double reading,
                        std::vector<std::string>* warnings) {
  const TermEstimate* term = fit.find(term_kind_name(kind));
  const double fitted = value_or_bound(term);
  if (!std::isfinite(reading) || !std::isfinite(fitted) ||
      !(reading > kReadingDisagreementRatio * fitted)) {
    return;
  }
  const std::string symbol = amplitude_symbol(kind);
  const std::string carriers = dominant_terms_at(fit, tau_s, kind);
  warnings->push_back(
      "slope reading of " + symbol + " at tau = " + format_number(tau_s) + " s (" +
      format_number(reading) + ") is " + format_number(reading / fitted) + "x the fitted " +
      symbol + (term->status == TermStatus::kPresent ? "" : " upper bound") + " (" +
      format_number(fitted) + "): the curve there is carried by " + carriers +
      (carriers.find("markov") != std::string::npos
           ? " (seed 003 Figs. 6.9-6.12: a Markov flank posing as white noise)"
           : ""));
}

void warn_white_rate(const FitResult& fit, std::vector<std::string>* warnings) {
  warn_slope_reading(fit, TermKind::kWhiteRate, 1.0, fit.graphical.white_rate_at_1s, warnings);
  const TermEstimate* white = fit.find("white_rate");
  // A low-pass filter shows as a leftmost point (with its large EDF) well below the fitted
  // white noise alone; noisy long-tau points touching the ray are not evidence of it.
  const FitPoint& leftmost = fit.points.front();
  if (white != nullptr && white->status == TermStatus::kPresent &&
      fit.model.white_rate_corner_hz <= 0.0) {
    const double white_only_avar =
        term_avar(Term{TermKind::kWhiteRate, white->amplitude.value, 0.0}, leftmost.tau_s);
    const double tolerance = 3.0 * std::sqrt(2.0 / leftmost.edf);
    if (leftmost.avar < white_only_avar * (1.0 - std::max(0.05, tolerance))) {
      warnings->push_back(
          "the leftmost point (tau = " + format_number(leftmost.tau_s) + " s) lies " +
          format_number(100.0 * (1.0 - std::sqrt(leftmost.avar / white_only_avar))) +
          " % below the fitted white noise alone: a low-pass (anti-alias) filter pulls it down, "
          "so the slope -1/2 ray through it (" + format_number(fit.graphical.white_rate_upper_bound) +
          ") is no upper bound of N; set white_rate_corner_hz if known");
    }
  }
  for (size_t i = 0; i < fit.model.terms.size(); ++i) {
    const Term& term = fit.model.terms[i];
    if (term.kind == TermKind::kMarkov &&
        markov_acts_as_low_passed_white(term.shape, fit.points.front().tau_s) &&
        fit.model.white_rate_corner_hz <= 0.0) {
      warnings->push_back(fit.terms[i].name + " has T_c = " + format_number(term.shape) +
                          " s, below twice the shortest tau: it behaves like low-passed white "
                          "noise of density q_c T_c = " + format_number(term.amplitude) +
                          " (an anti-alias filter pulling the leftmost points down?); kalibr_imu.yaml's noise density "
                          "adds it to N in power");
    }
  }
}

void warn_bias_instability(const FitResult& fit, std::vector<std::string>* warnings) {
  const double reading = fit.graphical.bias_instability_from_minimum;
  const TermEstimate* bias = fit.find("bias_instability");
  const double fitted = value_or_bound(bias);
  if (!std::isfinite(reading) || !std::isfinite(fitted)) return;
  if (reading > kReadingDisagreementRatio * fitted) {
    warnings->push_back(
        "flat-tangent reading of B (minimum / 0.664 = " + format_number(reading) + " at tau = " +
        format_number(fit.graphical.tau_at_minimum_s) + " s) over-states the fitted B" +
        (bias->status == TermStatus::kPresent ? "" : " upper bound") + " (" +
        format_number(fitted) + ") " + format_number(reading / fitted) +
        "x: at the minimum the AVAR is mostly " +
        dominant_terms_at(fit, fit.graphical.tau_at_minimum_s, TermKind::kBiasInstability));
  }
}

}  // namespace

std::vector<std::string> fit_warnings(const FitResult& fit) {
  std::vector<std::string> warnings;
  warn_white_rate(fit, &warnings);
  warn_bias_instability(fit, &warnings);
  warn_slope_reading(fit, TermKind::kRandomWalk, 3.0, fit.graphical.random_walk_at_3s, &warnings);
  if (fit.quality.p_value < 0.01) {
    warnings.push_back("the model does not describe the curve (deviance " +
                       format_number(fit.quality.deviance) + " on " +
                       std::to_string(fit.quality.degrees_of_freedom) + " dof, p = " +
                       format_number(fit.quality.p_value) +
                       "): a term outside the model, or a non-stationary record");
  }
  for (const TermEstimate& term : fit.terms) {
    if (term.status == TermStatus::kUnconstrained) {
      warnings.push_back(term.name + " is in the model but the data do not constrain it: report "
                         "its upper bound " + format_number(term.amplitude.upper_bound) +
                         ", not its value");
    }
  }
  return warnings;
}

}  // namespace identify
}  // namespace imu_lab
