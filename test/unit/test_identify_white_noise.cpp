// Case 3: pure white rate noise. Model selection must report every other term absent (with an
// upper bound), not force small values onto them.
#include <gtest/gtest.h>

#include <cmath>

#include "identify_test_records.h"
#include "imu_lab/identify/fit.h"

namespace imu_lab {
namespace identify {
namespace {

constexpr double kRateHz = 100.0;
constexpr double kDurationS = 3600.0;
constexpr double kN_rad_per_sqrt_s = 1.75e-4;

TEST(IdentifyWhiteNoise, NoOtherTermIsReportedPresent) {
  for (std::uint64_t seed : {1, 2, 3}) {
    const auto rates =
        identify_test::emulate_axis_rates({noise::WhiteRateParameters{kN_rad_per_sqrt_s}}, kRateHz, kDurationS, seed);
    const FitResult fit = fit_noise_model(identify_test::octave_oadev(rates, kRateHz), 1.0 / kRateHz, kDurationS);
    ASSERT_EQ(fit.model.terms.size(), 1u) << "seed " << seed << ": " << fit.terms[1].name;
    const TermEstimate* white = fit.find("white_rate");
    ASSERT_NE(white, nullptr);
    EXPECT_EQ(white->status, TermStatus::kPresent);
    EXPECT_LT(std::abs(white->amplitude.value - kN_rad_per_sqrt_s), 3.0 * white->amplitude.sigma);
    for (const char* name : {"white_angle", "bias_instability", "random_walk", "rate_ramp"}) {
      const TermEstimate* term = fit.find(name);
      ASSERT_NE(term, nullptr) << name;
      EXPECT_EQ(term->status, TermStatus::kAbsent) << name;
      EXPECT_TRUE(std::isnan(term->amplitude.value)) << name;
      EXPECT_GT(term->amplitude.upper_bound, 0.0) << name;
      EXPECT_TRUE(std::isfinite(term->amplitude.upper_bound)) << name;
    }
    EXPECT_GT(fit.quality.p_value, 0.001);
  }
}

// The upper bound means what it says: a random walk just above the bound found on white noise
// would have raised the curve's right end visibly.
TEST(IdentifyWhiteNoise, RandomWalkBoundIsTight) {
  const auto rates =
      identify_test::emulate_axis_rates({noise::WhiteRateParameters{kN_rad_per_sqrt_s}}, kRateHz, kDurationS, 4);
  const FitResult fit = fit_noise_model(identify_test::octave_oadev(rates, kRateHz), 1.0 / kRateHz, kDurationS);
  const double bound = fit.find("random_walk")->amplitude.upper_bound;
  // At the longest fitted tau the bound's AVAR is comparable to the white noise's (not 100x
  // smaller: a loose bound; not 100x larger: a bound the data would contradict).
  const double tau = fit.points.back().tau_s;
  const double ratio = (bound * bound * tau / 3.0) / (kN_rad_per_sqrt_s * kN_rad_per_sqrt_s / tau);
  EXPECT_GT(ratio, 0.05);
  EXPECT_LT(ratio, 20.0);
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
