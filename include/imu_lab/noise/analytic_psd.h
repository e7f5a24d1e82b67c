// Rate PSDs of the noise processes whose AVARs noise/analytic_avar.h gives, in the convention of
// doc/noise_families.md eq. (1) (IEEE Std 952): S(f) two-sided, in u^2/Hz for a rate in u, so
//   AVAR(tau) = 4 int_0^inf S(f) sin^4(pi f tau) / (pi f tau)^2 df
// turns each of them into its AVAR (checked by that integral in test_noise_analytic_psd.cpp).
// Every function is even in f; a one-sided density (what spectrum::welch_psd reports) is 2 S.
#pragma once

#include <functional>

namespace imu_lab {
namespace noise {

double white_rate_psd(double density_per_sqrt_hz);  // N^2
// White angle error of per-sample sigma Q (the quantization model): the rate is its first
// difference over tau0, (4 Q^2 / tau0) sin^2(pi f tau0), about (2 pi f)^2 tau0 Q^2 well below
// the Nyquist frequency. Bandwidth-defined: it needs the sample interval.
double white_angle_psd(double per_sample_sigma, double tau0_s, double frequency_hz);
// Eq. 5.3's flicker: B^2 / (2 pi |f|) for |f| <= f0, zero above.
double bias_instability_psd(double coefficient, double cutoff_frequency_hz, double frequency_hz);
double random_walk_psd(double density_per_sqrt_s, double frequency_hz);  // (K / 2 pi)^2 / f^2
// (q_c T_c)^2 / (1 + (2 pi f T_c)^2); white noise N behind a first-order low-pass of corner f_c is
// this with T_c = 1 / (2 pi f_c), q_c T_c = N.
double markov_psd(double q_c_per_sqrt_s, double correlation_time_s, double frequency_hz);
// A sinusoid of peak amplitude Omega0 has no density: its power Omega0^2 / 2 sits in two lines,
// Omega0^2 / 4 [delta(f - f0) + delta(f + f0)]. This is the power of one of them.
double sinusoid_line_power(double amplitude);
// Krobka table 7.1 row 1: alpha |f|^n exp(-beta |f|).
double zero_dc_family_psd(double exponent_n, double alpha, double beta_s, double frequency_hz);
// Krobka table 7.1 row 2: alpha |f|^n exp(-beta f^2), beta in s^2.
double zero_dc_gaussian_psd(double exponent_n, double alpha, double beta_s2, double frequency_hz);
// Krobka table 7.3: alpha f^2 / (beta^2 + f^2), white rate noise of density sqrt(alpha) behind a
// first-order high-pass of corner beta [Hz].
double high_pass_white_psd(double alpha, double beta_hz, double frequency_hz);
// The damped second-order band-pass of resonance_avar: y = z', z'' + 2 zeta w_n z' + w_n^2 z =
// white of two-sided density 4 zeta w_n rms^2 (so that Var z = (rms / w_n)^2), zeta = width /
// (2 f_n):  S = 4 zeta w_n rms^2 w^2 / ((w_n^2 - w^2)^2 + (2 zeta w_n w)^2), w = 2 pi f.
// Throws std::invalid_argument unless 0 < width_hz < 2 natural_frequency_hz.
double resonance_psd(double rms, double natural_frequency_hz, double width_hz, double frequency_hz);

// The PSD of the samples a sensor reports every tau0, each the rate averaged over its interval:
// the averaging multiplies S by sinc^2(pi f tau0) and the sampling folds every alias onto
// |f| <= 1 / (2 tau0) (Papoulis, "Probability, Random Variables and Stochastic Processes", 2002,
// ch. 9-10):  S_d(f) = sum_k S(f + k / tau0) sinc^2(pi (f + k / tau0) tau0).
// This is what a Welch estimate of the record estimates. The sum runs over |k| <= alias_count;
// the tail left out is below 2 S_max / (pi^2 alias_count), S_max the largest S beyond
// (alias_count - 1/2) / tau0, so it suits a PSD that falls beyond the Nyquist frequency. A flat
// PSD needs no sum (S_d = S: the sinc^2 aliases sum to 1), nor does white_angle_psd (already
// periodic in f: S_d = S).
// Amplitude gain of averaging over tau0 at f: sinc(pi f tau0) = sin(pi f tau0) / (pi f tau0).
double interval_average_gain(double frequency_hz, double tau0_s);
double interval_averaged_psd(const std::function<double(double frequency_hz)>& psd, double frequency_hz, double tau0_s,
                             int alias_count = 256);

}  // namespace noise
}  // namespace imu_lab
