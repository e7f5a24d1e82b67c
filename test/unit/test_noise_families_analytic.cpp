// The closed-form AVARs of Krobka's zero-at-DC families (ICINS 2015, section 7;
// doc/noise_families.md) against the numerical integral of eq. 5.1, to 1e-6 relative, over tau
// from 0.1 to 30 times the PSD's own time scale; and against the printed tables where those are
// right, with the printed misprints shown.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <algorithm>
#include <cmath>
#include <complex>

#include "imu_lab/noise/analytic_avar.h"
#include "test_noise_avar_check.h"

namespace imu_lab {
namespace noise {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRelative = 1e-6;

// Dawson's function D(x) = e^{-x^2} int_0^x e^{t^2} dt = int_0^x e^{-s (2x - s)} ds (s = x - t),
// by quadrature (independent of 1F1); the integrand is below e^{-50} beyond s = 50 / x.
double dawson(double x) {
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      [&](double s) { return std::exp(-s * (2.0 * x - s)); }, 0.0, std::min(x, 50.0 / x), 15, 1e-15);
}

TEST(NoiseFamiliesAnalytic, ExponentialRowAgainstIntegral) {
  const double alpha = 1e-6, beta = 0.2;
  for (double n : {1.5, 2.0, 3.0, 4.5}) {
    const double f_max = (60.0 + 5.0 * n) / beta;
    for (double tau : {0.02, 0.3, 6.0}) {
      const double numeric =
          test::numerical_avar([&](double f) { return alpha * std::pow(f, n) * std::exp(-beta * f); }, tau, f_max);
      EXPECT_NEAR(numeric / zero_dc_family_avar(n, alpha, beta, tau), 1.0, kRelative) << "n " << n << " tau " << tau;
    }
  }
}

TEST(NoiseFamiliesAnalytic, CosineRowAgainstIntegral) {
  // The cosine row alone changes sign, so its error is measured against the exponential row's
  // AVAR, which bounds it (|S_cos| <= S_exp).
  const double alpha = 1e-6, beta = 0.2;
  for (double n : {1.5, 2.0, 3.0}) {
    for (double c : {0.3, 2.5}) {
      const double f_max = (60.0 + 5.0 * n) / beta;
      for (double tau : {0.02, 0.3, 6.0}) {
        const double numeric = test::numerical_avar(
            [&](double f) { return alpha * std::pow(f, n) * std::exp(-beta * f) * std::cos(c * f); }, tau, f_max);
        EXPECT_NEAR(numeric, zero_dc_cosine_avar(n, alpha, beta, c, tau),
                    kRelative * zero_dc_family_avar(n, alpha, beta, tau))
            << "n " << n << " c " << c << " tau " << tau;
      }
    }
  }
  // Table 7.1 row 3 as printed (Gamma(1 + n), powers -1 - n) is this row for f^(n+2):
  // alpha Gamma(n+1) / (2 pi^2 tau^2) Re[3 (b - ic)^(-1-n) - 2 (b - i(c - 2 pi tau))^(-1-n) - ...].
  const double n = 1.0, c = 0.3, tau = 0.3;
  using Complex = std::complex<double>;
  auto p = [&](double omega) { return std::pow(Complex(beta, -omega), -1.0 - n).real(); };
  const double printed = 4.0 * alpha / (kPi * kPi * tau * tau) * std::tgamma(1.0 + n) / 32.0 *
                         (12.0 * p(c) + 2.0 * p(c - 4 * kPi * tau) + 2.0 * p(c + 4 * kPi * tau) -
                          8.0 * p(c - 2 * kPi * tau) - 8.0 * p(c + 2 * kPi * tau));
  EXPECT_NEAR(printed / zero_dc_cosine_avar(n + 2.0, alpha, beta, c, tau), 1.0, 1e-12);
}

TEST(NoiseFamiliesAnalytic, GaussianRowsAgainstIntegral) {
  const double alpha = 1e-6, beta = 0.01;  // s^2: the PSD falls off near 1 / sqrt(beta) = 10 Hz
  const double f_max = std::sqrt(60.0 / beta);
  // tau = 0.2 and 0.25 put pi^2 tau^2 / beta on either side of 40, where 1F1 switches to its
  // large-argument expansion.
  for (double n : {1.5, 2.0, 3.0, 4.0, 5.5}) {
    for (double tau : {0.01, 0.1, 0.2, 0.25, 3.0}) {
      const double numeric =
          test::numerical_avar([&](double f) { return alpha * std::pow(f, n) * std::exp(-beta * f * f); }, tau, f_max);
      EXPECT_NEAR(numeric / zero_dc_gaussian_avar(n, alpha, beta, tau), 1.0, kRelative) << "n " << n << " tau " << tau;
    }
  }
}

TEST(NoiseFamiliesAnalytic, HighPassWhiteAgainstIntegral) {
  // S = alpha - alpha beta^2 / (beta^2 + f^2): the white part's AVAR is alpha / tau exactly, the
  // rest decays and is integrated numerically.
  const double alpha = 1e-6, beta = 0.5, f_max = 1000.0 * beta;
  for (double tau : {0.03, 0.3, 3.0, 30.0}) {
    const double numeric =
        alpha / tau +
        test::numerical_avar([&](double f) { return -alpha * beta * beta / (beta * beta + f * f); }, tau, f_max);
    // The Lorentzian's tail beyond f_max adds at most 4 alpha beta^2 / (3 pi^2 tau^2 f_max^3).
    const double tail = 4.0 * alpha * beta * beta / (3.0 * kPi * kPi * tau * tau * std::pow(f_max, 3));
    EXPECT_NEAR(numeric, high_pass_white_avar(alpha, beta, tau),
                kRelative * high_pass_white_avar(alpha, beta, tau) + tail)
        << tau;
    // Table 7.3 as printed, where it does not cancel.
    const double x = 2.0 * kPi * beta * tau;
    EXPECT_NEAR(alpha / (4.0 * beta * kPi * tau * tau) * (3.0 - 4.0 * std::exp(-x) + std::exp(-2.0 * x)) /
                    high_pass_white_avar(alpha, beta, tau),
                1.0, 1e-12);
  }
  // tau -> 0: the white noise alpha / tau (Krobka's asymptote sqrt(alpha) tau^(-1/2)).
  EXPECT_NEAR(high_pass_white_avar(alpha, beta, 1e-9) / (alpha / 1e-9), 1.0, 1e-8);
}

TEST(NoiseFamiliesAnalytic, PrintedTableRowsAndTheirMisprints) {
  const double alpha = 1e-6, beta = 0.2;
  for (double tau : {0.01, 0.1, 1.0, 10.0}) {
    const double a = beta * beta + 4.0 * kPi * kPi * tau * tau;
    const double b = beta * beta + 16.0 * kPi * kPi * tau * tau;
    // Table 7.2 row 2 (f^2 e^{-beta f}) with alpha, not the printed alpha^2.
    EXPECT_NEAR(96.0 * alpha * kPi * kPi * tau * tau / (beta * a * b) / zero_dc_family_avar(2.0, alpha, beta, tau), 1.0,
                1e-12);
    // Table 7.2 row 3 (f^3 e^{-beta f}): the correct numerator has 64 pi^4 tau^4, not 60.
    const double correct =
        96.0 * alpha * kPi * kPi * tau * tau *
        (5 * std::pow(beta, 4) + 60 * beta * beta * kPi * kPi * tau * tau + 64 * std::pow(kPi * tau, 4)) /
        (beta * beta * a * a * b * b);
    EXPECT_NEAR(correct / zero_dc_family_avar(3.0, alpha, beta, tau), 1.0, 1e-12);
    // Table 7.2 row 4 (f^2 e^{-beta f^2}) and row 5 (the Dawson row, f^3 e^{-beta f^2}).
    const double bg = 0.01, x = kPi * tau / std::sqrt(bg);
    EXPECT_NEAR(alpha * (3.0 + std::exp(-4.0 * x * x) - 4.0 * std::exp(-x * x)) /
                    (4.0 * std::sqrt(bg) * std::pow(kPi, 1.5) * tau * tau) / zero_dc_gaussian_avar(2.0, alpha, bg, tau),
                1.0, 1e-12);
    EXPECT_NEAR(alpha / (std::pow(bg, 1.5) * kPi * tau) * (2.0 * dawson(x) - dawson(2.0 * x)) /
                    zero_dc_gaussian_avar(3.0, alpha, bg, tau),
                1.0, 1e-12)
        << tau;
  }
  // The printed f^3 row (60 pi^4 tau^4) is 16/15 too small at long tau.
  const double tau = 100.0;
  const double a = beta * beta + 4.0 * kPi * kPi * tau * tau;
  const double b = beta * beta + 16.0 * kPi * kPi * tau * tau;
  const double printed =
      96.0 * alpha * kPi * kPi * tau * tau *
      (5 * std::pow(beta, 4) + 60 * beta * beta * kPi * kPi * tau * tau + 60 * std::pow(kPi * tau, 4)) /
      (beta * beta * a * a * b * b);
  EXPECT_NEAR(zero_dc_family_avar(3.0, alpha, beta, tau) / printed, 16.0 / 15.0, 1e-6);
}

TEST(NoiseFamiliesAnalytic, StationaryAngleIdentityAndQuantization) {
  // The resonance through the identity, and the rounding noise as white noise per sample.
  const double rms = 1e-3, fn = 20.0, width = 1.5, tau = 0.07;
  const double sigma2 = std::pow(rms / (2 * kPi * fn), 2);
  EXPECT_NEAR(resonance_avar(rms, fn, width, tau),
              stationary_angle_avar(sigma2, sigma2 * resonance_angle_correlation(fn, width, tau),
                                    sigma2 * resonance_angle_correlation(fn, width, 2 * tau), tau),
              1e-15 * sigma2 / (tau * tau));
  EXPECT_DOUBLE_EQ(output_quantization_avar(0.3, 0.01, 0.01), 0.09 / 12.0);
  EXPECT_DOUBLE_EQ(output_quantization_avar(0.3, 0.1, 0.01), 0.09 / 120.0);
}

}  // namespace
}  // namespace noise
}  // namespace imu_lab
