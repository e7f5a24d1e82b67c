#include "imu_lab/noise/zero_dc_noise.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <utility>

#include <unsupported/Eigen/FFT>

#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace noise {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kMaxHalfWidth = std::size_t(1) << 16;
constexpr std::size_t kGridPerHalfWidth = 16;

std::size_t next_power_of_two(double value) {
  std::size_t result = 1;
  while (static_cast<double>(result) < value) result *= 2;
  return result;
}
}  // namespace

ZeroDcNoise::ZeroDcNoise(std::function<double(double)> angle_covariance, double time_scale_s, double echo_delay_s,
                         std::string kind, NormalStream normals)
    : angle_covariance_(std::move(angle_covariance)),
      time_scale_s_(time_scale_s),
      echo_delay_s_(echo_delay_s),
      kind_(std::move(kind)),
      normals_(normals) {}

ZeroDcNoise::ZeroDcNoise(const ZeroDcFamilyParameters& p, NormalStream normals)
    : ZeroDcNoise(
          [p](double lag) {
            double c = zero_dc_family_angle_covariance(p.exponent_n, p.alpha, p.beta_s, lag);
            if (p.cosine_weight != 0.0) {
              c += p.cosine_weight * zero_dc_cosine_angle_covariance(p.exponent_n, p.alpha, p.beta_s, p.cosine_s, lag);
            }
            return c;
          },
          // C(u) ~ 1 / (beta^2 + 4 pi^2 u^2)^((n-1)/2); the cosine adds an echo at c / (2 pi).
          p.beta_s / (2.0 * kPi), p.cosine_s / (2.0 * kPi), "zero_dc_family", normals) {
  if (!(p.exponent_n > 1.0) || !(p.alpha > 0.0) || !(p.beta_s > 0.0) || !(p.cosine_s >= 0.0) ||
      !(std::abs(p.cosine_weight) <= 1.0)) {
    throw std::invalid_argument("zero_dc_family: need n > 1, alpha > 0, beta > 0, cosine_s >= 0, |cosine_weight| <= 1");
  }
}

ZeroDcNoise::ZeroDcNoise(const ZeroDcGaussianParameters& p, NormalStream normals)
    : ZeroDcNoise([p](double lag) { return zero_dc_gaussian_angle_covariance(p.exponent_n, p.alpha, p.beta_s2, lag); },
                  std::sqrt(std::max(0.0, p.beta_s2)) / kPi, 0.0, "zero_dc_gaussian", normals) {
  if (!(p.exponent_n > 1.0) || !(p.alpha > 0.0) || !(p.beta_s2 > 0.0)) {
    throw std::invalid_argument("zero_dc_gaussian: need n > 1, alpha > 0, beta > 0");
  }
}

double ZeroDcNoise::analytic_avar(double tau_s) const {
  return stationary_angle_avar(angle_covariance_(0.0), angle_covariance_(tau_s), angle_covariance_(2.0 * tau_s), tau_s);
}

void ZeroDcNoise::build_taps(double h, std::size_t half_width) {
  // Sampled spectrum of c_k = C(k h), |k| <= grid / 2, then its square root back to taps.
  const std::size_t grid = kGridPerHalfWidth * half_width;
  std::vector<std::complex<double>> covariance(grid);
  for (std::size_t k = 0; k <= grid / 2; ++k) {
    const double c = angle_covariance_(static_cast<double>(k) * h);
    covariance[k] = c;
    if (k > 0 && k < grid / 2) covariance[grid - k] = c;
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, covariance);
  for (auto& value : spectrum) value = std::sqrt(std::max(0.0, value.real()));
  std::vector<std::complex<double>> response;
  fft.inv(response, spectrum);
  taps_.assign(2 * half_width + 1, 0.0);
  for (std::size_t j = 0; j <= 2 * half_width; ++j) {
    taps_[j] = response[(j + grid - half_width) % grid].real();
  }
}

double ZeroDcNoise::design_error(double h) const {
  double worst = 0.0;
  for (std::size_t m = 1; m <= 1000; m = m < 8 ? m + 1 : m + m / 8) {
    const double exact = analytic_avar(m * h);
    const double generated =
        (3.0 * generated_covariance(0) - 4.0 * generated_covariance(m) + generated_covariance(2 * m)) / (m * h * m * h);
    worst = std::max(worst, std::abs(generated / exact - 1.0));
  }
  return worst;
}

void ZeroDcNoise::design(double h) {
  if (h == designed_interval_s_) return;
  designed_interval_s_ = h;
  std::size_t half_width = next_power_of_two(256.0 * std::max(1.0, time_scale_s_ / h) + 4.0 * echo_delay_s_ / h);
  for (;;) {
    build_taps(h, half_width);
    max_relative_error_ = design_error(h);
    if (max_relative_error_ <= kZeroDcTolerance || half_width >= kMaxHalfWidth) break;
    half_width *= 2;
  }
  if (max_relative_error_ > kZeroDcTolerance) {
    throw std::invalid_argument(kind_ + ": the FIR generator misses the closed-form AVAR by " +
                                std::to_string(max_relative_error_) +
                                " at this sample interval (needs a covariance that decays faster)");
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
  if (tau0_s != designed_interval_s_) return analytic_avar(tau_s);
  const auto m = static_cast<std::size_t>(std::llround(tau_s / tau0_s));
  return (3.0 * generated_covariance(0) - 4.0 * generated_covariance(m) + generated_covariance(2 * m)) /
         (tau_s * tau_s);
}

double ZeroDcNoise::sample_variance(double h) const {
  if (h != designed_interval_s_) {
    return 2.0 * (angle_covariance_(0.0) - angle_covariance_(h)) / (h * h);
  }
  return 2.0 * (generated_covariance(0) - generated_covariance(1)) / (h * h);
}

double ZeroDcNoise::max_relative_error(double h) {
  design(h);
  return max_relative_error_;
}

}  // namespace noise
}  // namespace imu_lab
