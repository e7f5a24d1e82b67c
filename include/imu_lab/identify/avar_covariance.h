// Covariance of overlapping Allan variance estimates across averaging factors, under a Gaussian
// noise model (doc/models.md, "Covariance of the AVAR estimates"). Each estimate is a quadratic
// form of the data, nu_m = (1 / M_m) sum_k d_k^2 with d_k = (x[k+2m] - 2 x[k+m] + x[k]) / (sqrt 2 m
// tau0) and x the integrated rate, so by Isserlis' theorem
//   cov(nu_m, nu_n) = 2 / (M_m M_n) sum_h count(h) C_mn(h)^2,   C_mn(h) = cov(d^m_k, d^n_{k+h}).
// C_mn follows from the model's generalised structure function D(u) (second differences of x
// annihilate constants and slopes, so a random walk or flicker rate has one too):
//   C_mn(h) = -1 / (4 m n tau0^2) sum_ij w_i w_j D((h + j n - i m) tau0),  w = (1, -2, 1).
// The sum over lags is exact near its kinks and Gauss-Legendre between them; it is the variance
// a parametric bootstrap would find, without simulating (Percival and Walden, "Wavelet Methods
// for Time Series Analysis", 2000, ch. 8, give the asymptotic form; Guerrier et al., JASA 2013,
// weight the generalized method of wavelet moments with it).
// Deterministic terms (rate ramp, sinusoid) carry no variance of their own, but they multiply
// the noise in the cross term of nu = (d^s + d)^2 averaged. A ramp's differences are the same
// constant c_m at every k, so it adds 4 c_m c_n cov(mean d^m, mean d^n), a linear lag sum of
// C_mn. A sinusoid's cross term is, on a record of many periods, the noise's Fourier component
// at the line times 4 sigma_s^2(tau_m) / Omega0^2 at every factor: it adds the nearly rank-one
// 4 sigma_s^2(tau_m) sigma_s^2(tau_n) S(f) / (Omega0^2 max(M_m, M_n) tau0), S the noise's
// one-sided rate density at the line (phase-averaged; checked against simulated records).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "imu_lab/identify/noise_model.h"

namespace imu_lab {
namespace identify {

// Generalised structure function of one term's integrated rate, D(u) = E[(x(t + u) - x(t))^2]
// where it exists; lag_s is a multiple of tau0_s (white angle error is per sample). Zero for
// deterministic terms.
double term_structure_function(const Term& term, double lag_s, double tau0_s);
double model_structure_function(const NoiseModel& model, double lag_s, double tau0_s);

// cov(nu_m, nu_n) for a record of sample_count rate samples every tau0_s, at fixed averaging
// factors, for any model. C_mn is linear in each term's amplitude squared, so the lag sums are
// kept per pair of unit-amplitude terms and reused by every later model that holds a term of the
// same kind and nearly the same shape (within 10 %: the covariance is a weight, its shape
// changes slowly with a term's): refitting amplitudes costs nothing, a new term one pass.
// The sums, and each unit's C_mn at the lags they visit, are also shared by every covariance of
// the same record (factors, tau0 and sample count) in the process, keyed by the unit's exact
// shape and the lags visited: the six axes of a record meet the same white, flicker and
// descriptive Markov terms. A shared sum is the one summed again would give, bit for bit.
class OavarCovariance {
 public:
  // Throws std::invalid_argument for a factor below 1 or above (sample_count - 1) / 2.
  OavarCovariance(std::vector<int> averaging_factors, double tau0_s, long long sample_count);
  ~OavarCovariance();
  OavarCovariance(const OavarCovariance&) = delete;
  OavarCovariance& operator=(const OavarCovariance&) = delete;

  Eigen::MatrixXd covariance(const NoiseModel& model);
  // The diagonal only (each estimate's variance); cheaper for many factors.
  std::vector<double> variance(const NoiseModel& model);

  // Estimates pooled over segments (a gap or a knock split the record) hold a fraction of the
  // terms one contiguous record would (allan::StabilityPoint::pooled_term_fraction), per factor.
  // Each variance then grows by its inverse and the correlations are kept: segments much longer
  // than 2 m average like one record of their summed length, and where a single segment
  // reaches, the fraction is that segment's share. Throws std::invalid_argument on a size
  // mismatch or a fraction outside (0, 1].
  void set_pooled_term_fractions(const std::vector<double>& fractions);

 private:
  struct Cache;
  std::unique_ptr<Cache> cache_;
};

// One-off forms of the above.
Eigen::MatrixXd oavar_covariance(const NoiseModel& model, const std::vector<int>& averaging_factors, double tau0_s,
                                 long long sample_count);
std::vector<double> oavar_variance(const NoiseModel& model, const std::vector<int>& averaging_factors, double tau0_s,
                                   long long sample_count);

// Brute-force sum over every lag (for tests; O(sample_count) per pair); a sinusoid's cross term
// summed exactly, averaged over its phase.
double oavar_covariance_by_direct_sum(const NoiseModel& model, int m, int n, double tau0_s, long long sample_count);

}  // namespace identify
}  // namespace imu_lab
