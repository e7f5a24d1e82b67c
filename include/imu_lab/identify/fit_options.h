// Options of the noise identification: which terms may enter, how bias instability's cutoff is
// chosen, the sensor's front end, the significance a term needs to be reported present, bounds.
#pragma once

#include <string>
#include <vector>

namespace imu_lab {
namespace identify {

// Eq. 5.3's cutoff f0 only shapes the curve for tau below ~1 / (pi f0); above it the flicker
// floor is flat. By default it is fixed at the Nyquist frequency 1 / (2 tau0): the flicker is
// then assumed to extend over the whole observed band, so at every observed tau (>= tau0,
// x = pi f0 tau >= pi / 2) the term has its textbook shape and B keeps its usual meaning.
// A given f0 (a datasheet value) or a fitted one (bounded to [1 / T, 1 / (2 tau0)]) are the
// alternatives; fitting it only pays when the white noise does not hide the short-tau roll-off.
enum class BiasCutoff { kNyquist, kGiven, kFitted };

struct FitOptions {
  bool allow_white_angle = true;
  bool allow_white_rate = true;
  bool allow_bias_instability = true;
  bool allow_random_walk = true;
  bool allow_rate_ramp = true;
  int max_markov_terms = 2;
  int max_sinusoids = 2;
  int max_resonances = 2;
  // Krobka 2015's zero-at-DC terms (section 7), off by default: their AVAR rises to a peak and
  // falls as 1 / tau^2, which a Markov or a white-angle term can also bend to; enable the one the
  // physics suggest (doc/identification.md).
  bool allow_zero_dc_family = false;    // table 7.1 row 1, PSD alpha f^2 exp(-beta f)
  bool allow_zero_dc_gaussian = false;  // table 7.1 row 2 (n = 2), PSD alpha f^2 exp(-beta f^2)
  bool allow_high_pass_white = false;   // table 7.3, PSD alpha f^2 / (beta^2 + f^2)

  BiasCutoff bias_cutoff = BiasCutoff::kNyquist;
  double bias_cutoff_hz = 0.0;  // for kGiven

  // The sensor's front end: a first-order low-pass on the white rate noise (the anti-alias
  // filter), its corner fitted when the data ask for it. A known corner (datasheet) can be
  // given instead; 0 = fitted (or none, if the data do not need one).
  bool allow_front_end = true;
  double front_end_corner_hz = 0.0;
  // The output's quantization step (LSB) in the rate unit, 0 = unquantised: rounding adds white
  // noise of variance step^2 / 12 per sample behind the front end. Known from the data.
  double output_quantization_step = 0.0;

  // Selection test level: a term enters, and stays, only if the GMM distance falls by more than
  // the chi2 quantile (1 - significance, its parameter count) (Bonferroni over the searched
  // shapes for terms whose shape is fitted).
  double significance = 0.01;
  // One-sided profile bound reported for absent and unconstrained terms.
  double upper_bound_confidence = 0.95;
  // A present term whose relative sigma exceeds this is reported unconstrained (+ upper bound).
  double unconstrained_relative_sigma = 1.0;
  // Starts of a new term, as fractions of its envelope amplitude (start_values.h).
  std::vector<double> envelope_fractions = {0.5, 0.1, 0.01};
  // Solves per candidate term in each selection step (the best starts by initial distance).
  int solves_per_candidate = 4;
};

// The names `allan --zero-dc-terms` takes: the zero-at-DC kinds' report names.
std::vector<std::string> zero_dc_term_names();
// Lets the zero-at-DC term of that report name ("zero_dc_family", "zero_dc_gaussian",
// "high_pass_white") enter the model; throws std::invalid_argument naming any other name.
void allow_zero_dc_term(const std::string& term_name, FitOptions* options);

}  // namespace identify
}  // namespace imu_lab
