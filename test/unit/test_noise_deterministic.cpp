// Deterministic terms checked analytically (tight tolerances), and the analytic AVAR formulas
// checked against a numerical evaluation of AVAR = 4 int S(f) sin^4(pi f tau)/(pi f tau)^2 df.
#include <gtest/gtest.h>

#include <cmath>

#include "imu_lab/allan/batch.h"
#include "imu_lab/noise/analytic_avar.h"
#include "imu_lab/noise/deterministic_noise.h"
#include "imu_lab/noise/flicker_bank.h"
#include "test_noise_avar_check.h"

namespace imu_lab {
namespace noise {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<double> phase_of(NoiseProcess& process, std::size_t count, double tau0) {
  std::size_t k = 0;
  return allan::phase_from_frequency(
      test::collect(count, [&]() { return process.next_interval_average(tau0 * k++, tau0); }), tau0);
}

TEST(NoiseDeterministic, RateRampAvarIsExact) {
  RateRampNoise ramp(RateRampParameters{2e-6});
  const auto phase = phase_of(ramp, 100000, 0.01);
  for (int m : {1, 10, 100, 1000, 10000}) {
    const double tau = m * 0.01;
    EXPECT_NEAR(allan::overlapping_allan_variance(phase, 0.01, m) / rate_ramp_avar(2e-6, tau), 1.0, 1e-6) << tau;
  }
}

TEST(NoiseDeterministic, SinusoidAvarMatchesEquation58) {
  // 400 whole periods of a 2 Hz sinusoid at 1 kHz: the time-averaged AVAR is eq. 5.8 up to
  // O(1 / periods) end terms.
  const double amplitude = 1e-3, frequency = 2.0, tau0 = 0.001;
  SinusoidNoise sinusoid(SinusoidParameters{amplitude, frequency, 0.3});
  const auto phase = phase_of(sinusoid, 200000, tau0);
  for (int m : {1, 10, 50, 100, 125, 200, 300, 700}) {
    const double tau = m * tau0;
    EXPECT_NEAR(allan::overlapping_allan_variance(phase, tau0, m), sinusoid_avar(amplitude, frequency, tau),
                5e-3 * amplitude * amplitude)
        << tau;
  }
}

TEST(NoiseDeterministic, SinusoidIntervalAverageIsExact) {
  // The average over [t, t+h] of sin(w t + p) against the closed-form antiderivative.
  SinusoidNoise sinusoid(SinusoidParameters{1.0, 3.0, 0.7});
  const double w = 2.0 * kPi * 3.0, h = 0.05;
  for (int k = 0; k < 50; ++k) {
    const double t = k * h;
    const double exact = (std::cos(w * t + 0.7) - std::cos(w * (t + h) + 0.7)) / (w * h);
    EXPECT_NEAR(sinusoid.next_interval_average(t, h), exact, 1e-13);
  }
}

TEST(NoiseAnalyticAvar, MarkovFlickerAndZeroDcAgainstNumericalIntegral) {
  for (double tau : {0.03, 0.3, 3.0}) {
    const double q = 1e-2, tc = 0.1;
    EXPECT_NEAR(test::numerical_avar([&](double f) { return q * q * tc * tc / (1.0 + std::pow(2 * kPi * f * tc, 2)); },
                                     tau, 200.0) /
                    markov_avar(q, tc, tau),
                1.0, 2e-3)
        << tau;
    const double b = 1e-3, f0 = 5.0;
    EXPECT_NEAR(test::numerical_avar([&](double f) { return f <= f0 ? b * b / (2 * kPi * f) : 0.0; }, tau, f0) /
                    bias_instability_avar(b, f0, tau),
                1.0, 1e-6)
        << tau;
    for (double n : {1.0, 2.0, 3.0, 2.5}) {
      const double alpha = 1e-6, beta = 0.2;
      EXPECT_NEAR(
          test::numerical_avar([&](double f) { return alpha * std::pow(f, n) * std::exp(-beta * f); }, tau, 300.0) /
              zero_dc_family_avar(n, alpha, beta, tau),
          1.0, 1e-6)
          << "n " << n << " tau " << tau;
    }
  }
}

TEST(NoiseAnalyticAvar, BiasInstabilityLimitsAndCosineIntegral) {
  EXPECT_NEAR(cosine_integral(1.0), 0.33740392290096813466, 1e-14);
  EXPECT_NEAR(cosine_integral(10.0), -0.045456433004455372635, 1e-14);
  // Leading series terms: gamma + ln x - x^2/4 + x^4/96.
  EXPECT_NEAR(cosine_integral(0.01), 0.57721566490153286 + std::log(0.01) - 2.5e-5 + 1e-8 / 96.0, 1e-15);
  // Long-tau plateau (2 ln2 / pi) B^2 of eq. 5.3.
  EXPECT_NEAR(bias_instability_avar(1.0, 1.0, 1e5) / (2.0 * std::log(2.0) / kPi), 1.0, 1e-5);
  // Continuous across the series / Ci switch at x = 1.
  const double x_switch = 1.0 / kPi;
  EXPECT_NEAR(bias_instability_avar(1.0, 1.0, x_switch * (1 - 1e-9)),
              bias_instability_avar(1.0, 1.0, x_switch * (1 + 1e-9)), 1e-8);
}

}  // namespace
}  // namespace noise
}  // namespace imu_lab
