#include "imu_lab/noise/resonance_noise.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace noise {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}

ResonanceNoise::ResonanceNoise(const ResonanceParameters& parameters, NormalStream normals)
    : parameters_(parameters), normals_(normals) {
  if (!(parameters.rms >= 0.0) || !(parameters.natural_frequency_hz > 0.0)) {
    throw std::invalid_argument("resonance: need rms >= 0 and natural frequency > 0");
  }
  resonance_angle_correlation(parameters.natural_frequency_hz, parameters.width_hz, 0.0);  // checks
  const double omega_n = kTwoPi * parameters.natural_frequency_hz;
  // Stationary start: z and z' are uncorrelated in the stationary state.
  state_[0] = parameters.rms / omega_n * normals_.next();
  state_[1] = parameters.rms * normals_.next();
}

void ResonanceNoise::prepare(double h) {
  if (h == prepared_interval_s_) return;
  prepared_interval_s_ = h;
  const double omega_n = kTwoPi * parameters_.natural_frequency_hz;
  const double zeta = parameters_.width_hz / (2.0 * parameters_.natural_frequency_hz);
  const double decay = zeta * omega_n;
  const double omega_d = omega_n * std::sqrt(1.0 - zeta * zeta);
  const double e = std::exp(-decay * h), c = std::cos(omega_d * h), s = std::sin(omega_d * h);
  // e^{A h}, A = [[0, 1], [-w_n^2, -2 zeta w_n]], underdamped.
  transition_ << e * (c + decay / omega_d * s), e * s / omega_d, -e * omega_n * omega_n / omega_d * s,
      e * (c - decay / omega_d * s);
  Eigen::Matrix2d stationary = Eigen::Matrix2d::Zero();
  stationary(0, 0) = std::pow(parameters_.rms / omega_n, 2);
  stationary(1, 1) = parameters_.rms * parameters_.rms;
  // The state is stationary, so the discrete noise makes up what the transition loses.
  Eigen::Matrix2d noise = stationary - transition_ * stationary * transition_.transpose();
  const double l11 = std::sqrt(std::max(0.0, noise(0, 0)));
  const double l21 = l11 > 0.0 ? 0.5 * (noise(1, 0) + noise(0, 1)) / l11 : 0.0;
  const double l22 = std::sqrt(std::max(0.0, noise(1, 1) - l21 * l21));
  noise_factor_ << l11, 0.0, l21, l22;
}

const Eigen::Matrix2d& ResonanceNoise::transition(double h) {
  prepare(h);
  return transition_;
}

const Eigen::Matrix2d& ResonanceNoise::noise_factor(double h) {
  prepare(h);
  return noise_factor_;
}

double ResonanceNoise::next_interval_average(double, double h) {
  prepare(h);
  const double previous_angle = state_[0];
  const Eigen::Vector2d normals(normals_.next(), normals_.next());
  state_ = transition_ * state_ + noise_factor_ * normals;
  return (state_[0] - previous_angle) / h;
}

double ResonanceNoise::allan_variance(double tau_s, double) const {
  return resonance_avar(parameters_.rms, parameters_.natural_frequency_hz, parameters_.width_hz, tau_s);
}

double ResonanceNoise::sample_variance(double h) const {
  // Var((z(t+h) - z(t)) / h) = 2 sigma_z^2 (1 - rho(h)) / h^2
  const double sigma_z = parameters_.rms / (kTwoPi * parameters_.natural_frequency_hz);
  const double rho = resonance_angle_correlation(parameters_.natural_frequency_hz, parameters_.width_hz, h);
  return 2.0 * sigma_z * sigma_z * (1.0 - rho) / (h * h);
}

HighPassWhiteNoise::HighPassWhiteNoise(const HighPassWhiteParameters& parameters, NormalStream normals)
    : parameters_(parameters),
      angle_propagator_(kTwoPi * parameters.corner_frequency_hz, parameters.density_per_sqrt_hz),
      normals_(normals) {
  if (!(parameters.density_per_sqrt_hz >= 0.0) || !(parameters.corner_frequency_hz > 0.0)) {
    throw std::invalid_argument("high_pass_white: need density >= 0 and corner frequency > 0");
  }
  angle_ = std::sqrt(angle_propagator_.stationary_variance()) * normals_.next();
}

double HighPassWhiteNoise::next_interval_average(double, double h) {
  const double previous_angle = angle_;
  angle_propagator_.advance_state(angle_, h, normals_.next());
  return (angle_ - previous_angle) / h;
}

double HighPassWhiteNoise::allan_variance(double tau_s, double) const {
  return high_pass_white_avar(parameters_.density_per_sqrt_hz * parameters_.density_per_sqrt_hz,
                              parameters_.corner_frequency_hz, tau_s);
}

double HighPassWhiteNoise::sample_variance(double h) const {
  const double alpha = parameters_.density_per_sqrt_hz * parameters_.density_per_sqrt_hz;
  const double f_c = parameters_.corner_frequency_hz;
  return 2.0 * (high_pass_white_angle_covariance(alpha, f_c, 0.0) - high_pass_white_angle_covariance(alpha, f_c, h)) /
         (h * h);
}

}  // namespace noise
}  // namespace imu_lab
