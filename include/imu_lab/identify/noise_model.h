// The noise model the identifier fits: AVAR(tau) = sum of independent terms (DESIGN.md section 5,
// seed 003 eqs. 5.2-5.8). Each term's AVAR is proportional to its amplitude squared; two-parameter
// terms also carry a shape parameter. "u" is the rate unit (rad/s, m/s^2), "v" its integral.
#pragma once

#include <string>
#include <vector>

namespace imu_lab {
namespace identify {

enum class TermKind {
  kWhiteAngle,       // Q [v], per-sample sigma of a white angle error: 3 Q^2 / tau^2
  kWhiteRate,        // N [u/sqrt(Hz)]: N^2 / tau (or its low-passed form, see NoiseModel)
  kBiasInstability,  // B [u], shape = cutoff f0 [Hz]: eq. 5.3
  kRandomWalk,       // K [u/sqrt(s)]: K^2 tau / 3
  kRateRamp,         // R [u/s]: R^2 tau^2 / 2
  kMarkov,           // amplitude = q_c T_c [u/sqrt(Hz)] (the density its flank mimics), shape = T_c [s]
  kSinusoid,         // peak Omega0 [u], shape = frequency [Hz]: eq. 5.8
  kZeroDcFamily,     // amplitude = sqrt(alpha) of PSD alpha f^2 exp(-beta f), shape = beta [s]
};

struct Term {
  TermKind kind = TermKind::kWhiteRate;
  double amplitude = 0.0;
  double shape = 0.0;  // unused (0) for the one-parameter terms
};

struct NoiseModel {
  std::vector<Term> terms;
  // Known first-order anti-alias corner applied to the white rate noise (0 = none): the
  // low-passed white noise is exactly a Markov process with T = 1 / (2 pi corner), q_c T = N.
  double white_rate_corner_hz = 0.0;
};

// "white_angle", "white_rate", "bias_instability", "random_walk", "rate_ramp", "markov",
// "sinusoid", "zero_dc_family" (the names noise::process_kind uses).
std::string term_kind_name(TermKind kind);
// Throws std::invalid_argument for an unknown name.
TermKind term_kind_from_name(const std::string& name);
// Whether the term has a shape parameter (Markov, sinusoid, bias instability, zero-DC family).
bool has_shape(TermKind kind);
// Symbol used in reports: Q, N, B, K, R, q_c_T_c, Omega0, sqrt_alpha.
std::string amplitude_symbol(TermKind kind);
// T_c, f, f0, beta; empty for one-parameter terms.
std::string shape_symbol(TermKind kind);

// AVAR contribution of one term at tau (the emulator's formulas in noise/analytic_avar.h).
double term_avar(const Term& term, double tau_s, double white_rate_corner_hz = 0.0);
double model_avar(const NoiseModel& model, double tau_s);

// Report names of the model's terms in order: kind names, Markov terms numbered by increasing
// correlation time ("markov_1", "markov_2").
std::vector<std::string> term_names(const NoiseModel& model);

// Canonical order: by kind, Markov terms by increasing correlation time.
bool term_order_less(const Term& a, const Term& b);

}  // namespace identify
}  // namespace imu_lab
