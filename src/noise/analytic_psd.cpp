#include "imu_lab/noise/analytic_psd.h"

#include <cmath>
#include <stdexcept>

namespace imu_lab {
namespace noise {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
}  // namespace

double white_rate_psd(double density) { return density * density; }

double white_angle_psd(double sigma, double tau0_s, double frequency_hz) {
  const double s = std::sin(kPi * frequency_hz * tau0_s);
  return 4.0 * sigma * sigma / tau0_s * s * s;
}

double bias_instability_psd(double coefficient, double cutoff_hz, double frequency_hz) {
  const double f = std::abs(frequency_hz);
  return f <= cutoff_hz ? coefficient * coefficient / (kTwoPi * f) : 0.0;
}

double random_walk_psd(double density, double frequency_hz) {
  const double amplitude = density / (kTwoPi * frequency_hz);
  return amplitude * amplitude;
}

double markov_psd(double q_c, double correlation_time_s, double frequency_hz) {
  const double low_frequency_density = q_c * correlation_time_s;
  const double x = kTwoPi * frequency_hz * correlation_time_s;
  return low_frequency_density * low_frequency_density / (1.0 + x * x);
}

double sinusoid_line_power(double amplitude) { return amplitude * amplitude / 4.0; }

double zero_dc_family_psd(double exponent_n, double alpha, double beta_s, double frequency_hz) {
  const double f = std::abs(frequency_hz);
  return alpha * std::pow(f, exponent_n) * std::exp(-beta_s * f);
}

double zero_dc_gaussian_psd(double exponent_n, double alpha, double beta_s2, double frequency_hz) {
  const double f = std::abs(frequency_hz);
  return alpha * std::pow(f, exponent_n) * std::exp(-beta_s2 * f * f);
}

double high_pass_white_psd(double alpha, double beta_hz, double frequency_hz) {
  const double f2 = frequency_hz * frequency_hz;
  return alpha * f2 / (beta_hz * beta_hz + f2);
}

double resonance_psd(double rms, double natural_frequency_hz, double width_hz, double frequency_hz) {
  if (!(width_hz > 0.0 && width_hz < 2.0 * natural_frequency_hz)) {
    throw std::invalid_argument("resonance PSD: the width must lie in (0, 2 f_n)");
  }
  const double zeta = width_hz / (2.0 * natural_frequency_hz);
  const double w_n = kTwoPi * natural_frequency_hz;
  const double w = kTwoPi * frequency_hz;
  const double stiffness = w_n * w_n - w * w;
  const double damping = 2.0 * zeta * w_n * w;
  return 4.0 * zeta * w_n * rms * rms * w * w / (stiffness * stiffness + damping * damping);
}

double interval_average_gain(double frequency_hz, double tau0_s) {
  const double x = kPi * frequency_hz * tau0_s;
  return std::abs(x) < 1e-8 ? 1.0 - x * x / 6.0 : std::sin(x) / x;
}

double interval_averaged_psd(const std::function<double(double)>& psd, double frequency_hz, double tau0_s,
                             int alias_count) {
  const double sample_rate_hz = 1.0 / tau0_s;
  double sum = 0.0;
  // Smallest terms first, so the far aliases are not lost against the central one.
  for (int k = alias_count; k >= 1; --k) {
    for (const double alias_hz : {frequency_hz + k * sample_rate_hz, frequency_hz - k * sample_rate_hz}) {
      const double gain = interval_average_gain(alias_hz, tau0_s);
      sum += psd(alias_hz) * gain * gain;
    }
  }
  const double gain = interval_average_gain(frequency_hz, tau0_s);
  return sum + psd(frequency_hz) * gain * gain;
}

}  // namespace noise
}  // namespace imu_lab
