// Analytic Allan variances of the rate (DESIGN.md section 5, seed 003 eqs. 5.2-5.8 and
// table 7.2). All are exact for interval-averaged samples at tau = m tau0 except where noted.
#pragma once

namespace imu_lab {
namespace noise {

// Cosine integral Ci(x) = -integral_x^inf cos(t)/t dt, x > 0.
double cosine_integral(double x);

double white_rate_avar(double density_per_sqrt_hz, double tau_s);             // N^2 / tau
// White angle error of per-sample sigma Q (quantization model): 3 Q^2 / tau^2.
double white_angle_avar(double per_sample_sigma, double tau_s);
// Physical pulse rounding of weight S (with carry): the white-angle formula with Q = S/sqrt(12),
// valid while other noise moves the angle by several pulses per sample.
double pulse_quantization_avar(double pulse_weight, double tau_s);
// Eq. 5.3: flicker B^2 / (2 pi f) below the cutoff f0.
double bias_instability_avar(double coefficient, double cutoff_frequency_hz, double tau_s);
double random_walk_avar(double density_per_sqrt_s, double tau_s);              // K^2 tau / 3
double rate_ramp_avar(double slope_per_s, double tau_s);                       // R^2 tau^2 / 2
// Eq. 5.7 (q_c, T_c), evaluated stably for tau << T_c.
double markov_avar(double q_c_per_sqrt_s, double correlation_time_s, double tau_s);
// Eq. 5.8, peak amplitude Omega0 (time average over a long record).
double sinusoid_avar(double amplitude, double frequency_hz, double tau_s);
// Seed 003 table 7.1, rate PSD alpha f^n exp(-beta f), any real n > 1; n = 1 from table 7.2.
// (Table 7.2's f^2 row misprints alpha^2 for alpha; its f^3 row disagrees with table 7.1 and
// with the numerical integral of eq. 5.1 by ~6 %, so it is not used.)
double zero_dc_family_avar(double exponent_n, double alpha, double beta_s, double tau_s);
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
