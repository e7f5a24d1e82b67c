// Case 2: a fibre-optic gyro whose short-correlation Markov hump screens the white noise
// (Krobka 2015 Figs. 6.9-6.12). The slope -1/2 segment around 1 s is the Markov flank, 40x the
// white noise; the fit must find N itself (from the shortest taus) and warn about the reading.
// Sigmas from the bootstrap (an option beside the default moment covariance).
#include <gtest/gtest.h>

#include <cmath>

#include "identify_test_records.h"
#include "imu_lab/identify/bootstrap.h"
#include "imu_lab/identify/fit.h"

namespace imu_lab {
namespace identify {
namespace {

constexpr double kRateHz = 2000.0;
constexpr double kDurationS = 600.0;
constexpr double kN_rad_per_sqrt_s = 2.9e-7;             // 0.001 deg/sqrt(h)
constexpr double kMarkovFlank_rad_per_sqrt_s = 1.16e-5;  // q_c T_c = 0.04 deg/sqrt(h)
constexpr double kCorrelationTime_s = 0.01;
constexpr double kB_rad_s = 1.5e-8;  // 0.003 deg/h, hidden under the flank

TEST(IdentifyFogHump, FindsTheWhiteNoiseUnderTheMarkovHump) {
  const std::vector<noise::ProcessParameters> truth = {
      noise::WhiteRateParameters{kN_rad_per_sqrt_s},
      noise::MarkovParameters{kMarkovFlank_rad_per_sqrt_s / kCorrelationTime_s, kCorrelationTime_s},
      noise::BiasInstabilityParameters{kB_rad_s, 100.0, 0.01, kDurationS}};
  const auto rates = identify_test::emulate_axis_rates(truth, kRateHz, kDurationS, 3);
  FitResult fit = fit_noise_model(identify_test::octave_oadev(rates, kRateHz), 1.0 / kRateHz, kDurationS);
  apply_bootstrap(bootstrap_uncertainty(fit, BootstrapOptions{12, 8}), &fit);

  // The slope reading at 1 s is off by at least 10x.
  EXPECT_GE(fit.graphical.white_rate_at_1s / kN_rad_per_sqrt_s, 10.0);

  const TermEstimate* white = fit.find("white_rate");
  ASSERT_NE(white, nullptr);
  ASSERT_EQ(white->status, TermStatus::kPresent);
  EXPECT_EQ(white->sigma_source, SigmaSource::kBootstrap);
  EXPECT_LT(std::abs(white->amplitude.value - kN_rad_per_sqrt_s), 3.0 * white->amplitude.sigma)
      << white->amplitude.value << " +- " << white->amplitude.sigma;
  EXPECT_LE(white->amplitude.sigma / white->amplitude.value, 0.25);

  const TermEstimate* markov = fit.find("markov_1");
  ASSERT_NE(markov, nullptr);
  EXPECT_EQ(markov->status, TermStatus::kPresent);
  EXPECT_LT(std::abs(markov->shape.value - kCorrelationTime_s), 3.0 * markov->shape.sigma);
  EXPECT_LT(std::abs(markov->amplitude.value - kMarkovFlank_rad_per_sqrt_s), 3.0 * markov->amplitude.sigma);
  EXPECT_EQ(fit.find("markov_2"), nullptr);

  // B is far below the flank in 10 min: reported absent, with a bound that holds the truth.
  const TermEstimate* bias = fit.find("bias_instability");
  ASSERT_NE(bias, nullptr);
  EXPECT_EQ(bias->status, TermStatus::kAbsent);
  EXPECT_GT(bias->amplitude.upper_bound, kB_rad_s);

  bool warned = false;
  for (const auto& warning : fit.warnings) {
    warned |= warning.find("slope reading of N") != std::string::npos && warning.find("markov_1") != std::string::npos;
  }
  EXPECT_TRUE(warned);
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
