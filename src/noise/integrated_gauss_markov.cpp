#include "imu_lab/noise/integrated_gauss_markov.h"

#include <cmath>
#include <limits>

namespace imu_lab {
namespace noise {

namespace {
// (1 - e^{-u}) / u and (1 - e^{-2u}) / (2u), both -> 1 at u = 0.
double one_minus_exp_over(double u) { return u == 0.0 ? 1.0 : -std::expm1(-u) / u; }
}  // namespace

double integrated_markov_factor(double u) {
  if (u < 0.1) {
    // g3(u) = sum_{k>=3} (-1)^{k+1} (2^k - 4) / (2 k!) u^{k-3}; direct form cancels badly here.
    double sum = 0.0, power = 1.0, factorial = 6.0, two_k = 8.0, sign = 1.0;
    for (int k = 3; k <= 14; ++k) {
      sum += sign * (two_k - 4.0) / (2.0 * factorial) * power;
      power *= u;
      factorial *= (k + 1);
      two_k *= 2.0;
      sign = -sign;
    }
    return sum;
  }
  // Beyond u = 40 the exponentials (under 2e-17) vanish beside 2u - 3 (>= 77, half an ulp >= 7e-15):
  // the same double without the two exp calls (the fit evaluates this at long taus very often).
  if (u >= 40.0) return (2.0 * u - 3.0) / (2.0 * u * u * u);
  return (2.0 * u - 3.0 + 4.0 * std::exp(-u) - std::exp(-2.0 * u)) / (2.0 * u * u * u);
}

IntegratedGaussMarkov::IntegratedGaussMarkov(double decay_rate_per_s, double drive_density)
    : decay_rate_per_s_(decay_rate_per_s), drive_density_(drive_density) {}

void IntegratedGaussMarkov::prepare(double h) {
  if (h == prepared_interval_s_) return;
  prepared_interval_s_ = h;
  const double u = decay_rate_per_s_ * h;
  const double q2 = drive_density_ * drive_density_;
  state_gain_ = std::exp(-u);
  integral_gain_ = h * one_minus_exp_over(u);
  const double var_state = q2 * h * one_minus_exp_over(2.0 * u);
  const double a = one_minus_exp_over(u);
  const double covariance = q2 * h * h * 0.5 * a * a;
  const double var_integral = q2 * h * h * h * integrated_markov_factor(u);
  chol_state_ = std::sqrt(var_state);
  chol_cross_ = chol_state_ > 0.0 ? covariance / chol_state_ : 0.0;
  chol_integral_ = std::sqrt(std::max(0.0, var_integral - chol_cross_ * chol_cross_));
}

double IntegratedGaussMarkov::advance(double& state, double h, double normal_1, double normal_2) {
  prepare(h);
  const double integral = integral_gain_ * state + chol_cross_ * normal_1 + chol_integral_ * normal_2;
  state = state_gain_ * state + chol_state_ * normal_1;
  return integral;
}

void IntegratedGaussMarkov::advance_state(double& state, double h, double normal) {
  prepare(h);
  state = state_gain_ * state + chol_state_ * normal;
}

double IntegratedGaussMarkov::stationary_variance() const {
  if (decay_rate_per_s_ <= 0.0) return std::numeric_limits<double>::infinity();
  return drive_density_ * drive_density_ / (2.0 * decay_rate_per_s_);
}

double IntegratedGaussMarkov::stationary_average_variance(double h) const {
  if (decay_rate_per_s_ <= 0.0) return 0.0;
  // Var(integral of stationary OU over h) / h^2 = q^2 h (u - 1 + e^{-u}) / u^3.
  const double u = decay_rate_per_s_ * h;
  const double numerator = u < 1e-3 ? u * u * (0.5 - u / 6.0 + u * u / 24.0) : u + std::expm1(-u);
  return drive_density_ * drive_density_ * h * numerator / (u * u * u);
}

}  // namespace noise
}  // namespace imu_lab
