#include "imu_lab/noise/analytic_avar.h"

#include <cmath>
#include <complex>
#include <stdexcept>

#include "imu_lab/noise/integrated_gauss_markov.h"

namespace imu_lab {
namespace noise {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

double white_rate_avar(double density, double tau) { return density * density / tau; }

double white_angle_avar(double sigma, double tau) { return 3.0 * sigma * sigma / (tau * tau); }

double pulse_quantization_avar(double pulse_weight, double tau) {
  return white_angle_avar(pulse_weight / std::sqrt(12.0), tau);
}

double bias_instability_avar(double coefficient, double cutoff_hz, double tau) {
  const double x = kPi * cutoff_hz * tau;
  const double s = std::sin(x);
  const double shape_term = s * s * s * (s + 4.0 * x * std::cos(x)) / (2.0 * x * x);
  double log_and_ci;  // ln 2 + Ci(2x) - Ci(4x)
  if (x < 1.0) {
    // The logarithms cancel: sum_k (-1)^k x^{2k} (4^k - 16^k) / (2k (2k)!).
    double sum = 0.0, power = 1.0, factorial = 1.0, four_k = 1.0, sixteen_k = 1.0;
    for (int k = 1; k < 40; ++k) {
      power *= -x * x;
      factorial *= (2.0 * k - 1.0) * (2.0 * k);
      four_k *= 4.0;
      sixteen_k *= 16.0;
      sum += power * (four_k - sixteen_k) / (2.0 * k * factorial);
    }
    log_and_ci = sum;
  } else {
    log_and_ci = std::log(2.0) + cosine_integral(2.0 * x) - cosine_integral(4.0 * x);
  }
  return 2.0 * coefficient * coefficient / kPi * (log_and_ci - shape_term);
}

double random_walk_avar(double density, double tau) { return density * density * tau / 3.0; }

double rate_ramp_avar(double slope, double tau) { return slope * slope * tau * tau / 2.0; }

double markov_avar(double q_c, double correlation_time, double tau) {
  // (q_c T_c)^2/tau [1 - T_c/(2 tau)(3 - 4 e^{-tau/T_c} + e^{-2 tau/T_c})] = q_c^2 tau g3(tau/T_c)
  return q_c * q_c * tau * integrated_markov_factor(tau / correlation_time);
}

double sinusoid_avar(double amplitude, double frequency_hz, double tau) {
  const double x = kPi * frequency_hz * tau;
  const double s = std::sin(x);
  return amplitude * amplitude * std::pow(s * s / x, 2.0);
}

double zero_dc_family_avar(double n, double alpha, double beta, double tau) {
  if (n == 1.0) {  // table 7.2, first row
    const double a = beta * beta + 4.0 * kPi * kPi * tau * tau;
    const double c = beta * beta + 16.0 * kPi * kPi * tau * tau;
    return -alpha / (4.0 * kPi * kPi * tau * tau) *
           (std::log(c) - 4.0 * std::log(a) + 6.0 * std::log(beta));
  }
  if (!(n > 1.0)) throw std::invalid_argument("zero_dc_family_avar: n must be >= 1");
  // Table 7.1: alpha Gamma(n-1) / (4 pi^2 tau^2) * 2 Re[3 beta^(1-n) - 4 (beta - 2 i pi tau)^(1-n)
  //            + (beta - 4 i pi tau)^(1-n)]
  using Complex = std::complex<double>;
  const double power = 1.0 - n;
  const Complex bracket = 3.0 * std::pow(Complex(beta, 0.0), power) -
                          4.0 * std::pow(Complex(beta, -2.0 * kPi * tau), power) +
                          std::pow(Complex(beta, -4.0 * kPi * tau), power);
  return alpha * std::tgamma(n - 1.0) / (2.0 * kPi * kPi * tau * tau) * bracket.real();
}

double resonance_angle_correlation(double natural_frequency_hz, double width_hz, double lag_s) {
  if (!(width_hz > 0.0) || !(width_hz < 2.0 * natural_frequency_hz)) {
    throw std::invalid_argument("resonance: need 0 < width < 2 natural frequency (underdamped)");
  }
  const double omega_n = 2.0 * kPi * natural_frequency_hz;
  const double zeta = width_hz / (2.0 * natural_frequency_hz);
  const double root = std::sqrt(1.0 - zeta * zeta);
  const double u = std::abs(lag_s);
  return std::exp(-zeta * omega_n * u) *
         (std::cos(omega_n * root * u) + zeta / root * std::sin(omega_n * root * u));
}

double resonance_avar(double rms, double natural_frequency_hz, double width_hz, double tau) {
  const double angle_sigma = rms / (2.0 * kPi * natural_frequency_hz);
  const double rho_1 = resonance_angle_correlation(natural_frequency_hz, width_hz, tau);
  const double rho_2 = resonance_angle_correlation(natural_frequency_hz, width_hz, 2.0 * tau);
  return angle_sigma * angle_sigma * (3.0 - 4.0 * rho_1 + rho_2) / (tau * tau);
}

}  // namespace noise
}  // namespace imu_lab
