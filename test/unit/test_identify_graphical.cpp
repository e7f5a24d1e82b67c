// The graphical readings on curves with known answers, and the anti-alias filter: a MEMS
// low-pass pulls the leftmost points down; the fit models it as the front end.
#include <gtest/gtest.h>

#include <cmath>

#include "identify_test_records.h"
#include "imu_lab/identify/fit.h"
#include "imu_lab/identify/graphical_readings.h"

namespace imu_lab {
namespace identify {
namespace {

std::vector<allan::StabilityPoint> analytic_curve(const NoiseModel& model) {
  std::vector<allan::StabilityPoint> points;
  for (double tau = 0.01; tau < 1e4; tau *= 2.0) {
    allan::StabilityPoint p;
    p.tau_s = tau;
    p.deviation = std::sqrt(model_avar(model, tau));
    p.edf = 100.0;
    points.push_back(p);
  }
  return points;
}

TEST(IdentifyGraphical, SingleTermReadingsAreExact) {
  NoiseModel white;
  white.terms = {{TermKind::kWhiteRate, 2e-4, 0.0}};
  const GraphicalReadings w = read_graphically(analytic_curve(white));
  EXPECT_NEAR(w.white_rate_upper_bound, 2e-4, 1e-12);
  EXPECT_NEAR(w.white_rate_at_1s, 2e-4, 1e-12);  // log-log interpolation is exact on a power law

  NoiseModel walk;
  walk.terms = {{TermKind::kRandomWalk, 3e-6, 0.0}};
  EXPECT_NEAR(read_graphically(analytic_curve(walk)).random_walk_at_3s, 3e-6, 1e-14);

  NoiseModel flicker;
  flicker.terms = {{TermKind::kBiasInstability, 5e-6, 50.0}};
  const GraphicalReadings f = read_graphically(analytic_curve(flicker));
  // Eq. 5.3's sharp cutoff leaves a ripple near tau ~ 1 / f0: its minimum dips 8 % under 0.664 B.
  EXPECT_NEAR(f.bias_instability_from_minimum / 5e-6, 0.92, 0.005);
}

TEST(IdentifyGraphical, MixtureMinimumOverstatesB) {
  NoiseModel mixture;
  mixture.terms = {{TermKind::kWhiteRate, 4.4e-5, 0.0},
                   {TermKind::kBiasInstability, 1.49e-5, 5.0},
                   {TermKind::kRandomWalk, 3.2e-5, 0.0}};
  const GraphicalReadings r = read_graphically(analytic_curve(mixture));
  EXPECT_GT(r.bias_instability_from_minimum / 1.49e-5, 4.0);
}

// The anti-alias low-pass pulls the leftmost points down. Blind, the fit finds the front end
// (white rate noise behind a fitted first-order corner) and reports N as N; told the corner, it
// keeps it. Without the front end in the model, N would come out low or sit in a Markov term.
TEST(IdentifyGraphical, AntiAliasFilterIsFittedOrTaken) {
  constexpr double kRateHz = 100.0, kDurationS = 1800.0, kN = 1.75e-4, kCornerHz = 30.0;
  const auto rates =
      identify_test::emulate_axis_rates({noise::WhiteRateParameters{kN}}, kRateHz, kDurationS, 21, kCornerHz);
  const auto curve = identify_test::octave_oadev(rates, kRateHz);
  const FitResult blind = fit_noise_model(curve, 1.0 / kRateHz, kDurationS);
  const TermEstimate* white = blind.find("white_rate");
  ASSERT_NE(white, nullptr);
  ASSERT_EQ(white->status, TermStatus::kPresent);
  EXPECT_TRUE(white->shape_fitted);
  EXPECT_LT(std::abs(std::log(white->amplitude.value / kN)), 3.0 * white->amplitude.log_sigma);
  EXPECT_LT(std::abs(std::log(white->shape.value / kCornerHz)), 3.0 * white->shape.log_sigma);
  EXPECT_EQ(blind.find("markov_1"), nullptr) << "the low-pass is the front end, not a Markov term";

  FitOptions options;
  options.front_end_corner_hz = kCornerHz;
  const FitResult informed = fit_noise_model(curve, 1.0 / kRateHz, kDurationS, options);
  white = informed.find("white_rate");
  ASSERT_NE(white, nullptr);
  EXPECT_FALSE(white->shape_fitted);
  EXPECT_DOUBLE_EQ(white->shape.value, kCornerHz);
  EXPECT_LT(std::abs(std::log(white->amplitude.value / kN)), 3.0 * white->amplitude.log_sigma);
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
