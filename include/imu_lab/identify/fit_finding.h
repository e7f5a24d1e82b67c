// One of the identification's warnings as data, so that a report can group and word them for
// its reader (the allan tool's console, pipeline/noise_table.h) while noise.yaml keeps each
// warning's full sentence (`text`). fit_warnings.h finds them.
#pragma once

#include <limits>
#include <string>

#include "imu_lab/identify/noise_model.h"

namespace imu_lab {
namespace identify {

enum class FindingKind {
  kSlopeReading,         // a slope reading (N at 1 s, K at 3 s) well above the fitted term or its bound
  kMarkovAsWhite,        // a Markov term with T_c below twice the shortest tau: low-passed white noise
  kFlatTangentReading,   // B read from the curve's minimum over-states the fitted B
  kDiscrepancy,          // the model describes the curve less well than the estimates' precision
  kBandExcursion,        // the fitted total leaves the measured curve's 95 % band over a range of taus
  kPartialAboveBand,     // a term's own partial curve exceeds the band's upper bound
  kOutweighedStructure,  // another structure has the larger Akaike weight
  kUnconstrained,        // a term in the model that the data do not constrain
  kBorderline,           // a term whose selection statistic was close to its threshold
};

struct FitFinding {
  static constexpr double kNotAvailable = std::numeric_limits<double>::quiet_NaN();
  FindingKind kind = FindingKind::kDiscrepancy;
  // The term concerned ("random_walk", "markov_1"); for an outweighing structure the term it adds
  // or the one it describes differently.
  std::string term;
  TermKind term_kind = TermKind::kWhiteRate;
  std::string alternative;             // outweighing structure: "random_walk added", "sinusoid_1 as a resonance"
  double first_tau_s = kNotAvailable;  // where: the reading's tau, the excursion's first tau
  double last_tau_s = kNotAvailable;   // the excursion's last tau
  // SI amplitude of a reading or of an unconstrained term's bound; the discrepancy or the largest
  // band excursion as a fraction (excursion: positive above the band).
  double value = kNotAvailable;
  double fitted = kNotAvailable;  // SI: the fitted amplitude (or its bound) a reading is set against
  bool fitted_is_bound = false;   // the term is not in the model: `fitted` is its upper bound
  std::string carriers;           // the terms that carry the AVAR where a reading was taken
  std::string text;               // the warning's full sentence (noise.yaml)
};

}  // namespace identify
}  // namespace imu_lab
