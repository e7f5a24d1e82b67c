// Case 1: a MEMS mixture (Q, N, B, K) whose Allan minimum sits at ~2 s, where the flat-tangent
// reading over-states B more than 4x (Krobka 2015 Fig. 6.5). The fit must recover every term within
// 3 reported sigma, with the bootstrap's honest sigmas: B to 25 %, N and K to 10 %.
#include <gtest/gtest.h>

#include <cmath>

#include "identify_test_records.h"
#include "imu_lab/identify/bootstrap.h"
#include "imu_lab/identify/fit.h"
#include "imu_lab/identify/record_length.h"

namespace imu_lab {
namespace identify {
namespace {

// 24 h at 10 Hz: B carries only ~6 % of the AVAR at the minimum, so it needs a long record
// (the random walk's correlated long-tau points roughly double B's Cramér-Rao sigma).
constexpr double kRateHz = 10.0;
constexpr double kDurationS = 24.0 * 3600.0;
constexpr double kQ_rad = 4.4e-6;
constexpr double kN_rad_per_sqrt_s = 4.4e-5;  // 0.15 deg/sqrt(h)
constexpr double kB_rad_s = 1.49e-5;          // 3.1 deg/h
constexpr double kK_rad_s_per_sqrt_s = 3.2e-5;

FitResult fit_case_one(std::uint64_t seed, bool with_bootstrap) {
  const std::vector<noise::ProcessParameters> truth = {
      noise::WhiteRateParameters{kN_rad_per_sqrt_s},
      noise::BiasInstabilityParameters{kB_rad_s, kRateHz / 2.0, 2.0 / kRateHz, kDurationS},
      noise::RandomWalkParameters{kK_rad_s_per_sqrt_s}, noise::WhiteAngleParameters{kQ_rad, 0.0}};
  const auto rates = identify_test::emulate_axis_rates(truth, kRateHz, kDurationS, seed);
  FitResult fit = fit_noise_model(identify_test::octave_oadev(rates, kRateHz), 1.0 / kRateHz, kDurationS);
  if (with_bootstrap) apply_bootstrap(bootstrap_uncertainty(fit, BootstrapOptions{20, 5}), &fit);
  return fit;
}

void expect_recovered(const FitResult& fit, const std::string& name, double truth, double max_relative_sigma) {
  const TermEstimate* term = fit.find(name);
  ASSERT_NE(term, nullptr) << name;
  ASSERT_EQ(term->status, TermStatus::kPresent) << name;
  EXPECT_EQ(term->sigma_source, SigmaSource::kBootstrap);
  const double sigma = term->amplitude.sigma;
  EXPECT_LT(std::abs(term->amplitude.value - truth), 3.0 * sigma)
      << name << " = " << term->amplitude.value << " +- " << sigma << ", truth " << truth;
  EXPECT_LE(sigma / term->amplitude.value, max_relative_sigma) << name;
}

TEST(IdentifyMemsMixture, RecoversEveryTermWhereTheFlatTangentOverstatesB) {
  const FitResult fit = fit_case_one(11, true);
  // The trap is set: the flat tangent over-states B at least 4x.
  EXPECT_GE(fit.graphical.bias_instability_from_minimum / kB_rad_s, 4.0);
  EXPECT_GT(fit.graphical.tau_at_minimum_s, 1.0);
  EXPECT_LT(fit.graphical.tau_at_minimum_s, 5.0);

  expect_recovered(fit, "white_angle", kQ_rad, 0.25);
  expect_recovered(fit, "white_rate", kN_rad_per_sqrt_s, 0.10);
  expect_recovered(fit, "bias_instability", kB_rad_s, 0.25);
  expect_recovered(fit, "random_walk", kK_rad_s_per_sqrt_s, 0.10);
  EXPECT_EQ(fit.model.terms.size(), 4u) << "no Markov, sinusoid or ramp invented";
  ASSERT_NE(fit.find("rate_ramp"), nullptr);
  EXPECT_EQ(fit.find("rate_ramp")->status, TermStatus::kAbsent);
  EXPECT_GT(fit.find("rate_ramp")->amplitude.upper_bound, 0.0);

  bool warned_about_minimum = false;
  for (const auto& warning : fit.warnings) {
    warned_about_minimum |= warning.find("flat-tangent reading of B") != std::string::npos;
  }
  EXPECT_TRUE(warned_about_minimum);
  EXPECT_GT(fit.quality.p_value, 0.001);

  // The fit says how long a record B needs for 15 %; with sigma ~ 1 / sqrt(T) that is about
  // T (sigma / 0.15)^2 (not exactly: longer records also add longer taus).
  const TermEstimate* bias = fit.find("bias_instability");
  const double relative_sigma = bias->amplitude.sigma / bias->amplitude.value;
  const double scaling_guess_s = kDurationS * std::pow(relative_sigma / 0.15, 2.0);
  const double needed_s = required_record_length_s(fit, "bias_instability", 0.15);
  EXPECT_GT(needed_s, scaling_guess_s / 1.5) << "B sigma " << relative_sigma;
  EXPECT_LT(needed_s, scaling_guess_s * 1.5) << "B sigma " << relative_sigma;
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
