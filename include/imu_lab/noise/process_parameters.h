// Parameters of one noise process on one sensor axis, as read from a profile. SI units throughout:
// "u" below is the triad's rate unit (rad/s for gyros, m/s^2 for accelerometers) and "v" its
// integral (rad, m/s). Continuous-time densities are per sqrt(Hz) (two-sided PSD convention of
// IEEE Std 952, doc/models.md), never per-sample values.
#pragma once

#include <string>
#include <variant>
#include <vector>

namespace imu_lab {
namespace noise {

// Angle/velocity random walk: rate PSD N^2.
struct WhiteRateParameters {
  double density_per_sqrt_hz = 0.0;  // N [u/sqrt(Hz)]
};

// Flicker bias instability B with cutoff f0 (eq. 5.3), realised as a bank of first-order Markov
// processes that tracks eq. 5.3 over [tau_min_s, tau_max_s] (the range the profile claims).
struct BiasInstabilityParameters {
  double coefficient = 0.0;          // B [u]
  double cutoff_frequency_hz = 0.0;  // f0
  double tau_min_s = 0.0;
  double tau_max_s = 0.0;
};

// Rate random walk: rate PSD (K / 2 pi)^2 / f^2; the rate starts at zero.
struct RandomWalkParameters {
  double density_per_sqrt_s = 0.0;  // K [u/sqrt(s)]
};

// Deterministic rate ramp R t, t measured from the emulator's start time.
struct RateRampParameters {
  double slope_per_s = 0.0;  // R [u/s]
};

// First-order Gauss-Markov: db = -b / T_c dt + q_c dW; PSD (q_c T_c)^2 / (1 + (2 pi f T_c)^2).
struct MarkovParameters {
  double q_c_per_sqrt_s = 0.0;      // q_c [u/sqrt(s)]
  double correlation_time_s = 0.0;  // T_c
};

// Omega0 sin(2 pi f0 t + phase), t measured from the emulator's start time.
struct SinusoidParameters {
  double amplitude = 0.0;  // peak Omega0 [u]
  double frequency_hz = 0.0;
  double phase_rad = 0.0;
};

// White noise of the integrated quantity ("white noise in angle"). Bandwidth-defined: either a
// fixed per-sample angle error sigma (the white-angle quantization model, Q) or a continuous
// density of the angle, whose per-sample variance density^2 / tau0 then depends on the rate.
struct WhiteAngleParameters {
  double per_sample_sigma = 0.0;     // Q [v]; used when density is 0
  double density_per_sqrt_hz = 0.0;  // sqrt(Q' tau0'^2) of Krobka 2015 [v/sqrt(Hz)]
};

// Krobka's zero-at-DC families (ICINS 2015, section 7; doc/noise_families.md), each generated
// as the derivative of a stationary angle (zero_dc_noise.h). Rate PSD
//   alpha |f|^n exp(-beta |f|) (1 + cosine_weight cos(cosine_s |f|)),  real n > 1,
// the exponential row of table 7.1 and, with cosine_weight != 0, its cosine row (|weight| <= 1
// keeps the PSD non-negative; the cosine row alone is not a PSD).
struct ZeroDcFamilyParameters {
  double exponent_n = 2.0;
  double alpha = 0.0;          // [u^2 / Hz^(n+1)]
  double beta_s = 0.0;         // [s]
  double cosine_s = 0.0;       // c [s]
  double cosine_weight = 0.0;  // w, |w| <= 1
};

// Rate PSD alpha |f|^n exp(-beta f^2), real n > 1 (table 7.1 row 2; n = 3 is the Dawson row).
struct ZeroDcGaussianParameters {
  double exponent_n = 2.0;
  double alpha = 0.0;    // [u^2 / Hz^(n+1)]
  double beta_s2 = 0.0;  // [s^2]
};

// Table 7.3, rate PSD alpha f^2 / (beta^2 + f^2): white rate noise N = sqrt(alpha) through a
// first-order high-pass with corner beta (AC coupling); generated exactly.
struct HighPassWhiteParameters {
  double density_per_sqrt_hz = 0.0;  // N = sqrt(alpha) [u/sqrt(Hz)]
  double corner_frequency_hz = 0.0;  // beta
};

// Damped second-order band-pass resonance (a mechanical mode): rate y = dz/dt with
// z'' + 2 zeta w_n z' + w_n^2 z = white, RMS rate `rms`, natural frequency f_n = w_n / 2 pi and
// -3 dB width 2 zeta f_n (< 2 f_n: underdamped). Generated exactly (resonance_noise.h).
struct ResonanceParameters {
  double rms = 0.0;  // [u]
  double natural_frequency_hz = 0.0;
  double width_hz = 0.0;
};

using ProcessParameters =
    std::variant<WhiteRateParameters, BiasInstabilityParameters, RandomWalkParameters, RateRampParameters,
                 MarkovParameters, SinusoidParameters, WhiteAngleParameters, ZeroDcFamilyParameters,
                 ResonanceParameters, HighPassWhiteParameters, ZeroDcGaussianParameters>;

// Short stable name ("white_rate", "markov", ...): used in RNG stream seeds and reports.
std::string process_kind(const ProcessParameters& parameters);

}  // namespace noise
}  // namespace imu_lab
