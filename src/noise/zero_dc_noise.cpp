#include "imu_lab/noise/zero_dc_noise.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include <unsupported/Eigen/FFT>

#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace noise {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Spectrum of the sampled covariance c_k = A / (a^2 + k^2) at angular frequency theta in
// [0, pi]: A pi / a * cosh(a (pi - theta)) / sinh(a pi), written to avoid overflow.
double sampled_spectrum(double scale, double a, double theta) {
  const double numerator = std::exp(-a * theta) * (1.0 + std::exp(-2.0 * a * (kPi - theta)));
  return scale * kPi / a * numerator / (-std::expm1(-2.0 * a * kPi));
}
}  // namespace

ZeroDcNoise::ZeroDcNoise(const ZeroDcFamilyParameters& parameters, NormalStream normals)
    : parameters_(parameters), normals_(normals) {
  if (parameters.exponent_n != 2 || !(parameters.alpha > 0.0) || !(parameters.beta_s > 0.0)) {
    throw std::invalid_argument("zero_dc_family: only n = 2 with alpha, beta > 0 is generated");
  }
}

void ZeroDcNoise::design(double h) {
  if (h == designed_interval_s_) return;
  designed_interval_s_ = h;
  // c_k = alpha/(4 pi^2) * 2 beta / (beta^2 + 4 pi^2 k^2 h^2) = A / (a^2 + k^2).
  const double a = parameters_.beta_s / (2.0 * kPi * h);
  const double scale = parameters_.alpha / (4.0 * kPi * kPi) * 2.0 * parameters_.beta_s /
                       (4.0 * kPi * kPi * h * h);
  // The taps decay like 1/k^2 beyond the kernel's width ~ a samples.
  const std::size_t half_width = std::min<std::size_t>(
      16384, static_cast<std::size_t>(std::ceil(256.0 * std::max(1.0, a))));
  const std::size_t grid = 16 * half_width;
  std::vector<std::complex<double>> root_spectrum(grid);
  for (std::size_t n = 0; n < grid; ++n) {
    const double theta = 2.0 * kPi * std::min(n, grid - n) / grid;
    root_spectrum[n] = std::sqrt(sampled_spectrum(scale, a, theta));
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> response;
  fft.inv(response, root_spectrum);
  taps_.assign(2 * half_width + 1, 0.0);
  for (std::size_t j = 0; j <= 2 * half_width; ++j) {
    const std::size_t index = (j + grid - half_width) % grid;
    taps_[j] = response[index].real();
  }
  history_.assign(taps_.size(), 0.0);
  for (double& deviate : history_) deviate = normals_.next();
  head_ = 0;
}

double ZeroDcNoise::next_interval_average(double, double h) {
  design(h);
  auto angle_now = [this]() {
    double sum = 0.0;
    const std::size_t size = taps_.size();
    for (std::size_t j = 0; j < size; ++j) sum += taps_[j] * history_[(head_ + j) % size];
    return sum;
  };
  if (!started_) {
    previous_angle_ = angle_now();
    started_ = true;
  }
  history_[head_] = normals_.next();  // drop the oldest deviate, take a new one
  head_ = (head_ + 1) % history_.size();
  const double angle = angle_now();
  const double average = (angle - previous_angle_) / h;
  previous_angle_ = angle;
  return average;
}

double ZeroDcNoise::generated_covariance(std::size_t lag) const {
  double sum = 0.0;
  for (std::size_t j = 0; j + lag < taps_.size(); ++j) sum += taps_[j] * taps_[j + lag];
  return sum;
}

double ZeroDcNoise::allan_variance(double tau_s, double tau0_s) const {
  if (tau0_s != designed_interval_s_) {
    return zero_dc_family_avar(2, parameters_.alpha, parameters_.beta_s, tau_s);
  }
  const auto m = static_cast<std::size_t>(std::llround(tau_s / tau0_s));
  return (3.0 * generated_covariance(0) - 4.0 * generated_covariance(m) +
          generated_covariance(2 * m)) / (tau_s * tau_s);
}

double ZeroDcNoise::sample_variance(double h) const {
  if (h != designed_interval_s_) return 0.0;
  return 2.0 * (generated_covariance(0) - generated_covariance(1)) / (h * h);
}

double ZeroDcNoise::max_relative_error(double h) {
  design(h);
  double worst = 0.0;
  for (std::size_t m = 1; m <= 1000; m = m < 8 ? m + 1 : m + m / 8) {
    const double tau = m * h;
    const double exact = zero_dc_family_avar(2, parameters_.alpha, parameters_.beta_s, tau);
    worst = std::max(worst, std::abs(allan_variance(tau, h) / exact - 1.0));
  }
  return worst;
}

}  // namespace noise
}  // namespace imu_lab
