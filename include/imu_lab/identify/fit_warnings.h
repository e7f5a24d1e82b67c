// Warnings that set the graphical readings against the fit, as Krobka section 6 describes (a
// slope -1/2 segment that is a Markov flank, a minimum that over-states B), and say where the
// model does not describe the curve: every tau range where the fitted total leaves the measured
// curve's 95 % band, a discrepancy the estimates needed, terms the data do not constrain, terms
// whose selection was borderline.
#pragma once

#include <string>
#include <vector>

#include "imu_lab/identify/fit_finding.h"
#include "imu_lab/identify/fit_result.h"

namespace imu_lab {
namespace identify {

// Ratio above which a reading is said to disagree with the fit.
constexpr double kReadingDisagreementRatio = 1.5;

// Contiguous runs of curve points where the fitted total is outside the band on one side: first
// and last tau, and the largest excursion beyond the band as a fraction of the measured deviation
// (positive: above the band). Neighbouring points on opposite sides make two runs.
struct BandExcursion {
  double first_tau_s = 0.0;
  double last_tau_s = 0.0;
  int point_count = 0;
  double largest_excursion = 0.0;
};
std::vector<BandExcursion> band_excursions(const std::vector<BandPoint>& band);

// Every warning about the fit, in the order noise.yaml lists them.
std::vector<FitFinding> fit_findings(const FitResult& fit);
// Their sentences.
std::vector<std::string> fit_warnings(const std::vector<FitFinding>& findings);

}  // namespace identify
}  // namespace imu_lab
