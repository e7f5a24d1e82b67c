// Analytic Allan variances of the rate (doc/models.md, Krobka 2015 eqs. 5.2-5.8 and
// table 7.2). All are exact for interval-averaged samples at tau = m tau0 except where noted.
#pragma once

namespace imu_lab {
namespace noise {

// Cosine integral Ci(x) = -integral_x^inf cos(t)/t dt, x > 0.
double cosine_integral(double x);

double white_rate_avar(double density_per_sqrt_hz, double tau_s);  // N^2 / tau
// White angle error of per-sample sigma Q (quantization model): 3 Q^2 / tau^2.
double white_angle_avar(double per_sample_sigma, double tau_s);
// Physical pulse rounding of weight S (with carry): the white-angle formula with Q = S/sqrt(12),
// valid while other noise moves the angle by several pulses per sample.
double pulse_quantization_avar(double pulse_weight, double tau_s);
// Eq. 5.3: flicker B^2 / (2 pi f) below the cutoff f0.
double bias_instability_avar(double coefficient, double cutoff_frequency_hz, double tau_s);
double random_walk_avar(double density_per_sqrt_s, double tau_s);  // K^2 tau / 3
double rate_ramp_avar(double slope_per_s, double tau_s);           // R^2 tau^2 / 2
// Eq. 5.7 (q_c, T_c), evaluated stably for tau << T_c.
double markov_avar(double q_c_per_sqrt_s, double correlation_time_s, double tau_s);
// Eq. 5.8, peak amplitude Omega0 (time average over a long record).
double sinusoid_avar(double amplitude, double frequency_hz, double tau_s);
// A rate that is the derivative of a stationary angle with covariance C(u): its interval average
// over tau is (angle(t + tau) - angle(t)) / tau, so AVAR = (3 C(0) - 4 C(tau) + C(2 tau)) / tau^2
// (doc/noise_families.md). Every zero-at-DC family below, and the resonance, has this form.
double stationary_angle_avar(double covariance_0, double covariance_tau, double covariance_2tau, double tau_s);

// The zero-at-DC families of Krobka (ICINS 2015 round table, section 7, tables 7.1-7.3), rate
// PSD S(f) (two-sided, as in eq. 5.1), derived in doc/noise_families.md and checked against the
// integral of eq. 5.1 (test_noise_families_analytic.cpp).
// Each has an angle covariance C(u) = 2 int_0^inf S(f) / (2 pi f)^2 cos(2 pi f u) df, which is
// what the emulator's generators realise.
//
// S = alpha f^n exp(-beta f), any real n > 1 (table 7.1 row 1); n = 1 from table 7.2 row 1.
// (Table 7.2's f^2 row misprints alpha^2 for alpha; its f^3 row disagrees with table 7.1 and
// with the numerical integral of eq. 5.1 by ~6 %, so it is not used.)
double zero_dc_family_avar(double exponent_n, double alpha, double beta_s, double tau_s);
// C(u) = alpha Gamma(n - 1) / (2 pi^2) Re (beta - 2 pi i u)^(1 - n), n > 1.
double zero_dc_family_angle_covariance(double exponent_n, double alpha, double beta_s, double lag_s);
// The cosine row alone, S = alpha f^n exp(-beta f) cos(c f), n > 1 (table 7.1 row 3 as printed
// belongs to alpha f^(n+2) exp(-beta f) cos(c f)). S < 0 at some f, so it is a PSD only as part
// of a sum such as alpha f^n exp(-beta f) (1 + w cos(c f)), |w| <= 1; its AVAR can be negative.
double zero_dc_cosine_avar(double exponent_n, double alpha, double beta_s, double cosine_s, double tau_s);
// C(u) = alpha Gamma(n - 1) / (4 pi^2) Re[(beta - i (c + 2 pi u))^(1-n) + (beta - i (c - 2 pi u))^(1-n)].
double zero_dc_cosine_angle_covariance(double exponent_n, double alpha, double beta_s, double cosine_s, double lag_s);
// S = alpha f^n exp(-beta f^2), real n > 1 (table 7.1 row 2; n = 2 and n = 3, the Dawson row, are
// table 7.2 rows 4 and 5): C(u) = alpha / (4 pi^2) beta^((1-n)/2) Gamma((n-1)/2)
// 1F1((n-1)/2; 1/2; -pi^2 u^2 / beta). beta in s^2.
double zero_dc_gaussian_avar(double exponent_n, double alpha, double beta_s2, double tau_s);
double zero_dc_gaussian_angle_covariance(double exponent_n, double alpha, double beta_s2, double lag_s);
// S = alpha f^2 / (beta^2 + f^2) (table 7.3): white rate noise of density sqrt(alpha) through a
// first-order high-pass with corner beta [Hz]; the angle is a first-order Markov process,
// C(u) = alpha exp(-2 pi beta |u|) / (4 pi beta).
double high_pass_white_avar(double alpha, double beta_hz, double tau_s);
double high_pass_white_angle_covariance(double alpha, double beta_hz, double lag_s);
// Rounding every output sample to an LSB: white, variance LSB^2 / 12 per sample (while other
// noise spans several LSBs), so AVAR = LSB^2 tau0 / (12 tau). Bandwidth-defined (depends on tau0).
double output_quantization_avar(double lsb, double tau_s, double tau0_s);
// A damped second-order band-pass resonance in the rate (a mechanical mode: y = dz/dt with
// z'' + 2 zeta w_n z' + w_n^2 z = white), of RMS rate `rms`, natural frequency f_n and -3 dB width
// 2 zeta f_n (zeta < 1). Its integral z is stationary with variance (rms / w_n)^2 and
// correlation rho(u) = e^{-zeta w_n u} (cos w_d u + zeta / sqrt(1 - zeta^2) sin w_d u), so
// AVAR = (rms / w_n)^2 (3 - 4 rho(tau) + rho(2 tau)) / tau^2.
double resonance_avar(double rms, double natural_frequency_hz, double width_hz, double tau_s);
// rho(u) above; throws std::invalid_argument unless 0 < width_hz < 2 natural_frequency_hz.
double resonance_angle_correlation(double natural_frequency_hz, double width_hz, double lag_s);

}  // namespace noise
}  // namespace imu_lab
