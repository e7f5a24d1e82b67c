// Options of the noise identification: which terms may enter, how bias instability's cutoff is
// chosen, the significance a term needs to be reported present, robustness and bounds.
#pragma once

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
  bool allow_sinusoid = true;
  bool allow_zero_dc_family = false;  // seed 003 table 7.1, PSD alpha f^2 exp(-beta f)

  BiasCutoff bias_cutoff = BiasCutoff::kNyquist;
  double bias_cutoff_hz = 0.0;  // for kGiven

  // Known first-order anti-alias corner of the white rate noise (0 = none / unknown). When it
  // is unknown and the filter pulls the leftmost points down, the fit describes the low-passed
  // white noise as a short Markov term and says so in a warning.
  double white_rate_corner_hz = 0.0;

  // Likelihood-ratio test level: a term enters, and stays, only if it improves the
  // log-likelihood by more than chi2 quantile (1 - significance, its parameter count) / 2.
  double significance = 0.001;
  // Huber threshold on the deviance residual (0 = plain maximum likelihood).
  double robust_loss_scale = 3.0;
  // One-sided profile-likelihood bound reported for absent and unconstrained terms.
  double upper_bound_confidence = 0.95;
  // A present term whose relative sigma exceeds this is reported unconstrained (+ upper bound).
  double unconstrained_relative_sigma = 1.0;
  // Starts of a new term, as fractions of its envelope amplitude (start_values.h).
  std::vector<double> envelope_fractions = {0.5, 0.1, 0.01};
  // Solves per candidate term in each selection step (the best starts by initial cost).
  int solves_per_candidate = 6;
};

}  // namespace identify
}  // namespace imu_lab
