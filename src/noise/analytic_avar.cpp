#include "imu_lab/noise/analytic_avar.h"

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include <boost/math/special_functions/hypergeometric_1F1.hpp>

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

double stationary_angle_avar(double covariance_0, double covariance_tau, double covariance_2tau, double tau) {
  return (3.0 * covariance_0 - 4.0 * covariance_tau + covariance_2tau) / (tau * tau);
}

namespace {
using Complex = std::complex<double>;

void require_exponent_above_one(double n, const char* family) {
  if (!(n > 1.0)) throw std::invalid_argument(std::string(family) + ": need n > 1");
}

// Re (beta - i omega)^(1 - n): the Laplace-Fourier integral
// int_0^inf f^(n-2) e^{-beta f} cos(omega f) df = Gamma(n - 1) Re (beta - i omega)^(1 - n).
double real_power(double beta, double omega, double n) { return std::pow(Complex(beta, -omega), 1.0 - n).real(); }

// Kummer's 1F1(a; 1/2; -z), z >= 0. Beyond z = 40 the large-argument expansion (DLMF 13.7.2)
// Gamma(1/2) / Gamma(1/2 - a) z^(-a) sum_s (a)_s (a + 1/2)_s / (s! z^s), summed to its smallest
// term, is exact to double precision (the neglected part is O(e^{-z})); boost's series does not
// reach z ~ 1e9, which long lags need.
double kummer_half(double a, double z) {
  if (z <= 40.0) return boost::math::hypergeometric_1F1(a, 0.5, -z);
  const double b_minus_a = 0.5 - a;
  if (b_minus_a <= 0.0 && b_minus_a == std::floor(b_minus_a)) return 0.0;  // e^{-z} times a polynomial
  double term = 1.0, sum = 1.0;
  for (int s = 0; s < 200; ++s) {
    const double next = term * (a + s) * (a + 0.5 + s) / ((s + 1.0) * z);
    if (std::abs(next) >= std::abs(term) || std::abs(next) < 1e-17 * std::abs(sum)) break;
    term = next;
    sum += term;
  }
  return std::sqrt(kPi) / std::tgamma(b_minus_a) * std::pow(z, -a) * sum;
}

template <typename Covariance>
double avar_of_angle(const Covariance& covariance, double tau) {
  return stationary_angle_avar(covariance(0.0), covariance(tau), covariance(2.0 * tau), tau);
}
}  // namespace

double zero_dc_family_angle_covariance(double n, double alpha, double beta, double lag) {
  require_exponent_above_one(n, "zero_dc_family");
  return alpha * std::tgamma(n - 1.0) / (2.0 * kPi * kPi) * real_power(beta, 2.0 * kPi * lag, n);
}

double zero_dc_family_avar(double n, double alpha, double beta, double tau) {
  if (n == 1.0) {  // table 7.2, first row (the angle variance diverges, the AVAR does not)
    const double a = beta * beta + 4.0 * kPi * kPi * tau * tau;
    const double c = beta * beta + 16.0 * kPi * kPi * tau * tau;
    return -alpha / (4.0 * kPi * kPi * tau * tau) * (std::log(c) - 4.0 * std::log(a) + 6.0 * std::log(beta));
  }
  if (!(n > 1.0)) throw std::invalid_argument("zero_dc_family_avar: n must be >= 1");
  // = table 7.1 row 1: alpha Gamma(n-1) / (2 pi^2 tau^2) Re[3 beta^(1-n)
  //   - 4 (beta - 2 i pi tau)^(1-n) + (beta - 4 i pi tau)^(1-n)]
  return avar_of_angle([&](double lag) { return zero_dc_family_angle_covariance(n, alpha, beta, lag); }, tau);
}

double zero_dc_cosine_angle_covariance(double n, double alpha, double beta, double c, double lag) {
  require_exponent_above_one(n, "zero_dc_family cosine");
  // cos(c f) cos(2 pi u f) = [cos((c + 2 pi u) f) + cos((c - 2 pi u) f)] / 2
  return alpha * std::tgamma(n - 1.0) / (4.0 * kPi * kPi) *
         (real_power(beta, c + 2.0 * kPi * lag, n) + real_power(beta, c - 2.0 * kPi * lag, n));
}

double zero_dc_cosine_avar(double n, double alpha, double beta, double c, double tau) {
  return avar_of_angle([&](double lag) { return zero_dc_cosine_angle_covariance(n, alpha, beta, c, lag); }, tau);
}

double zero_dc_gaussian_angle_covariance(double n, double alpha, double beta_s2, double lag) {
  require_exponent_above_one(n, "zero_dc_gaussian");
  if (!(beta_s2 > 0.0)) throw std::invalid_argument("zero_dc_gaussian: need beta > 0");
  // int_0^inf f^(n-2) e^{-beta f^2} cos(w f) df = beta^((1-n)/2) Gamma((n-1)/2) / 2
  //   * 1F1((n-1)/2; 1/2; -w^2 / (4 beta)), w = 2 pi u.
  const double a = 0.5 * (n - 1.0);
  const double kummer = kummer_half(a, kPi * kPi * lag * lag / beta_s2);
  return alpha / (4.0 * kPi * kPi) * std::pow(beta_s2, -a) * std::tgamma(a) * kummer;
}

double zero_dc_gaussian_avar(double n, double alpha, double beta_s2, double tau) {
  return avar_of_angle([&](double lag) { return zero_dc_gaussian_angle_covariance(n, alpha, beta_s2, lag); }, tau);
}

double high_pass_white_angle_covariance(double alpha, double beta_hz, double lag) {
  return alpha * std::exp(-2.0 * kPi * beta_hz * std::abs(lag)) / (4.0 * kPi * beta_hz);
}

double high_pass_white_avar(double alpha, double beta_hz, double tau) {
  // Table 7.3, alpha / (4 pi beta tau^2) (3 - 4 e^{-x} + e^{-2x}), x = 2 pi beta tau, written
  // as alpha / tau (1 - x^2 g3(x)) (3 - 4 e^{-x} + e^{-2x} = 2x - 2x^3 g3(x)) to stay exact for
  // x -> 0: the white noise's alpha / tau less the AVAR of its low-passed part.
  const double x = 2.0 * kPi * beta_hz * tau;
  return alpha / tau * (1.0 - x * x * integrated_markov_factor(x));
}

double output_quantization_avar(double lsb, double tau, double tau0) {
  return white_rate_avar(lsb * std::sqrt(tau0 / 12.0), tau);
}

double resonance_angle_correlation(double natural_frequency_hz, double width_hz, double lag_s) {
  if (!(width_hz > 0.0) || !(width_hz < 2.0 * natural_frequency_hz)) {
    throw std::invalid_argument("resonance: need 0 < width < 2 natural frequency (underdamped)");
  }
  const double omega_n = 2.0 * kPi * natural_frequency_hz;
  const double zeta = width_hz / (2.0 * natural_frequency_hz);
  const double root = std::sqrt(1.0 - zeta * zeta);
  const double u = std::abs(lag_s);
  // e^-746 is below half the smallest subnormal: the envelope is exactly 0 there, and the
  // oscillation (a slow sincos at such arguments) need not be evaluated.
  const double exponent = -zeta * omega_n * u;
  if (exponent < -746.0) return 0.0;
  return std::exp(exponent) * (std::cos(omega_n * root * u) + zeta / root * std::sin(omega_n * root * u));
}

double resonance_avar(double rms, double natural_frequency_hz, double width_hz, double tau) {
  const double angle_sigma = rms / (2.0 * kPi * natural_frequency_hz);
  const double rho_1 = resonance_angle_correlation(natural_frequency_hz, width_hz, tau);
  const double rho_2 = resonance_angle_correlation(natural_frequency_hz, width_hz, 2.0 * tau);
  return angle_sigma * angle_sigma * stationary_angle_avar(1.0, rho_1, rho_2, tau);
}

}  // namespace noise
}  // namespace imu_lab
