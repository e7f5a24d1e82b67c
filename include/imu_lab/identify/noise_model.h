// The noise model the identifier fits: AVAR(tau) = sum of independent terms (doc/models.md,
// IEEE Std 952 annex C, Krobka eqs. 5.2-5.8). Each term's AVAR is proportional to its amplitude
// squared; two- and three-parameter terms also carry shape parameters. "u" is the rate unit
// (rad/s, m/s^2), "v" its integral (rad, m/s).
#pragma once

#include <string>
#include <vector>

namespace imu_lab {
namespace identify {

enum class TermKind {
  kWhiteAngle,       // Q [v], per-sample sigma of a white angle error: 3 Q^2 / tau^2
  kWhiteRate,        // N [u/sqrt(Hz)], shape = front-end low-pass corner [Hz] (0: none)
  kBiasInstability,  // B [u], shape = cutoff f0 [Hz]: eq. 5.3
  kRandomWalk,       // K [u/sqrt(s)]: K^2 tau / 3
  kRateRamp,         // R [u/s]: R^2 tau^2 / 2
  kMarkov,           // amplitude = q_c T_c [u/sqrt(Hz)] (the density its flank mimics), shape = T_c [s]
  kSinusoid,         // peak Omega0 [u], shape = frequency [Hz]: eq. 5.8
  kZeroDcFamily,     // amplitude = sqrt(alpha) of PSD alpha f^2 exp(-beta f), shape = beta [s]
  kResonance,        // RMS rate [u] of a damped second-order band-pass, shape = natural frequency
                     // [Hz], width = its -3 dB width [Hz] (2 zeta f_n)
  kZeroDcGaussian,   // amplitude = sqrt(alpha) of PSD alpha f^2 exp(-beta f^2), shape = beta [s^2]
  kHighPassWhite,    // amplitude = sqrt(alpha) [u/sqrt(Hz)] of PSD alpha f^2 / (beta^2 + f^2), shape =
                     // beta [Hz]: white rate noise behind a first-order high-pass (AC coupling)
};

struct Term {
  TermKind kind = TermKind::kWhiteRate;
  double amplitude = 0.0;
  double shape = 0.0;  // 0 for the one-parameter terms and for white rate without a front end
  double width = 0.0;  // resonance only
};

struct NoiseModel {
  std::vector<Term> terms;
  // White noise the output's rounding adds behind the front end, as a density: LSB / sqrt(12)
  // per sample is sqrt(tau0) LSB / sqrt(12) per sqrt(Hz). Known from the data, not fitted.
  double output_quantization_density = 0.0;
};

// "white_angle", "white_rate", "bias_instability", "random_walk", "rate_ramp", "markov",
// "sinusoid", "zero_dc_family", "resonance", "zero_dc_gaussian", "high_pass_white" (the names
// noise::process_kind uses).
std::string term_kind_name(TermKind kind);
// Throws std::invalid_argument for an unknown name.
TermKind term_kind_from_name(const std::string& name);
// Number of shape parameters a kind can carry: 0, 1 (Markov, sinusoid, bias instability, the
// zero-at-DC terms, white rate's front end) or 2 (resonance).
int shape_count(TermKind kind);
bool has_shape(TermKind kind);
// Symbol used in reports: Q, N, B, K, R, q_c_T_c, Omega0, sqrt_alpha, rms.
std::string amplitude_symbol(TermKind kind);
// T_c, f, f0, beta, f_n, low_pass_corner; empty for one-parameter terms.
std::string shape_symbol(TermKind kind);
// "width" for the resonance; empty otherwise.
std::string width_symbol(TermKind kind);

// AVAR contribution of one term at tau (the emulator's formulas in noise/analytic_avar.h; a
// white rate term with a front end is the first-order low-passed white noise, exactly a Markov
// process with T_c = 1 / (2 pi corner) and q_c T_c = N).
double term_avar(const Term& term, double tau_s);
// The terms plus the output quantization.
double model_avar(const NoiseModel& model, double tau_s);

// Two-sided PSD of one term's rate at f [u^2/Hz], the density whose integral (doc/noise_families.md
// eq. (1)) is term_avar (noise/analytic_psd.h). A sinusoid's power is in its two lines
// (noise::sinusoid_line_power at +-f) and a rate ramp, being deterministic, has no stationary
// PSD: both give 0 here. tau0_s is needed for the white angle term only.
double term_psd(const Term& term, double frequency_hz, double tau0_s);
// The PSD of the term's samples every tau0, each the interval average of the rate
// (noise::interval_averaged_psd), for |f| <= 1 / (2 tau0): what a Welch estimate of a record
// estimates. Lines and ramps give 0 as above.
double sampled_term_psd(const Term& term, double frequency_hz, double tau0_s);
// The terms plus the output quantization (white: N_q^2 in both).
double model_psd(const NoiseModel& model, double frequency_hz, double tau0_s);
double sampled_model_psd(const NoiseModel& model, double frequency_hz, double tau0_s);

// Report names of the model's terms in order: kind names, Markov terms numbered by increasing
// correlation time ("markov_1", "markov_2"), sinusoids and resonances by increasing frequency.
std::vector<std::string> term_names(const NoiseModel& model);

// Canonical order: by kind, numbered kinds by their shape.
bool term_order_less(const Term& a, const Term& b);

}  // namespace identify
}  // namespace imu_lab
