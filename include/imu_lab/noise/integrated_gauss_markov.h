// Exact discretisation of a first-order Gauss-Markov state b (db = -lambda b dt + q dW) jointly
// with its integral over one interval h: the pair (b(t+h), integral_t^{t+h} b) is Gaussian with
//   mean  = (e^{-u} b, h (1 - e^{-u}) / u * b),  u = lambda h
//   var b = q^2 h (1 - e^{-2u}) / (2u)
//   var I = q^2 h^3 g3(u),   g3(u) = (2u - 3 + 4 e^{-u} - e^{-2u}) / (2 u^3)
//   cov   = q^2 h^2 (1 - e^{-u})^2 / (2 u^2).
// lambda = 0 is the random walk (all factors take their limits 1, 1, 1/3, 1/2). One propagator
// serves Markov noise, rate random walk, the flicker bank, band-limited white noise and the
// Markov angle of high-pass white noise.
#pragma once

namespace imu_lab {
namespace noise {

// g3(u) above, with its series near u = 0 (g3(0) = 1/3). Also the Markov AVAR shape:
// AVAR(tau) = q^2 tau g3(tau / T_c) (doc/models.md; Krobka 2015 eq. 5.7).
double integrated_markov_factor(double u);

class IntegratedGaussMarkov {
 public:
  IntegratedGaussMarkov(double decay_rate_per_s, double drive_density);

  // Advances `state` by one interval of length interval_s using two independent standard
  // normals and returns the exact integral of the state over the interval.
  double advance(double& state, double interval_s, double normal_1, double normal_2);
  // Advances `state` alone (its exact AR(1) step) with one standard normal.
  void advance_state(double& state, double interval_s, double normal);

  double decay_rate_per_s() const { return decay_rate_per_s_; }
  double drive_density() const { return drive_density_; }
  // q^2 / (2 lambda); infinite for the random walk.
  double stationary_variance() const;
  // Variance of the interval average of the stationary process; 0 for the random walk.
  double stationary_average_variance(double interval_s) const;

 private:
  void prepare(double interval_s);

  double decay_rate_per_s_;
  double drive_density_;
  double prepared_interval_s_ = -1.0;
  double state_gain_ = 1.0;
  double integral_gain_ = 0.0;
  double chol_state_ = 0.0;  // lower Cholesky factor of the 2x2 covariance
  double chol_cross_ = 0.0;
  double chol_integral_ = 0.0;
};

}  // namespace noise
}  // namespace imu_lab
