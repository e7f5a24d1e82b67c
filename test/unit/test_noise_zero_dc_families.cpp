// The FIR generators of Krobka's zero-at-DC families (zero_dc_noise.h): each design's
// own AVAR within kZeroDcTolerance of the closed form over [tau0, 1000 tau0], and the emulated
// AVAR against the closed form (Bonferroni, each point at its exact EDF).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "imu_lab/noise/analytic_avar.h"
#include "imu_lab/noise/zero_dc_noise.h"
#include "test_noise_avar_check.h"

namespace imu_lab {
namespace noise {
namespace {

constexpr double kTau0 = 0.01;
constexpr std::size_t kSamples = std::size_t(1) << 19;  // 87 min at 100 Hz
constexpr int kMaxFactor = 1 << 13;

// The closed form is eq. (2) of doc/noise_families.md on the family's angle covariance, which is
// how zero_dc_family_avar and its siblings are computed (those are checked against the integral
// of eq. 5.1 in test_noise_families_analytic.cpp).
void expect_generator_matches(ZeroDcNoise& process, const std::function<double(double)>& covariance,
                              const std::string& what) {
  const auto closed_form = [&](double tau) {
    return stationary_angle_avar(covariance(0.0), covariance(tau), covariance(2.0 * tau), tau);
  };
  std::size_t k = 0;
  const auto rates = test::collect(kSamples, [&]() { return process.next_interval_average(kTau0 * k++, kTau0); });
  const double design_error = process.max_relative_error(kTau0);
  EXPECT_LE(design_error, kZeroDcTolerance) << what;
  // The generated covariance is zero beyond the FIR's length.
  const auto edf = test::stationary_angle_edf(covariance, kTau0, static_cast<long>(process.tap_count()), kMaxFactor);
  const test::AvarCheck check = test::check_avar(rates, kTau0, closed_form, 1, kMaxFactor, 0.997, edf);
  EXPECT_TRUE(check.passed()) << what << "\n" << check.table;
  std::printf("[zero-dc] %-44s taps %6zu  design error %.1e  worst |ratio-1|/sqrt(2/edf) = %.2f  rejected %d\n",
              what.c_str(), process.tap_count(), design_error, check.worst_normalised_deviation, check.rejected_points);
}

TEST(NoiseZeroDcFamilies, ExponentialRowOtherExponents) {
  for (double n : {1.5, 3.0, 4.5}) {
    const double alpha = 1e-6, beta = 0.05;
    ZeroDcNoise process(ZeroDcFamilyParameters{n, alpha, beta}, NormalStream(60 + static_cast<int>(2 * n)));
    expect_generator_matches(
        process, [&](double u) { return zero_dc_family_angle_covariance(n, alpha, beta, u); },
        "alpha f^" + std::to_string(n).substr(0, 3) + " exp(-beta f)");
  }
}

TEST(NoiseZeroDcFamilies, CosineRowAsAnEcho) {
  // alpha f^2 exp(-beta f) (1 + w cos(c f)): the exponential row plus w times the cosine row.
  const double n = 2.0, alpha = 1e-6, beta = 0.05, c = 0.6, w = 0.8;
  ZeroDcNoise process(ZeroDcFamilyParameters{n, alpha, beta, c, w}, NormalStream(66));
  expect_generator_matches(
      process,
      [&](double u) {
        return zero_dc_family_angle_covariance(n, alpha, beta, u) +
               w * zero_dc_cosine_angle_covariance(n, alpha, beta, c, u);
      },
      "alpha f^2 exp(-beta f) (1 + 0.8 cos(0.6 f))");
}

TEST(NoiseZeroDcFamilies, GaussianRowsIncludingTheDawsonRow) {
  for (double n : {2.0, 3.0, 2.5}) {
    const double alpha = 1e-6, beta = 4e-4;  // s^2: the PSD falls off near 50 Hz
    ZeroDcNoise process(ZeroDcGaussianParameters{n, alpha, beta}, NormalStream(70 + static_cast<int>(2 * n)));
    expect_generator_matches(
        process, [&](double u) { return zero_dc_gaussian_angle_covariance(n, alpha, beta, u); },
        "alpha f^" + std::to_string(n).substr(0, 3) + " exp(-beta f^2)");
  }
}

TEST(NoiseZeroDcFamilies, InvalidParametersRefused) {
  EXPECT_THROW(ZeroDcNoise(ZeroDcFamilyParameters{1.0, 1e-6, 0.05}, NormalStream(1)), std::invalid_argument);
  EXPECT_THROW(ZeroDcNoise(ZeroDcFamilyParameters{2.0, 1e-6, 0.05, 0.3, 1.5}, NormalStream(1)), std::invalid_argument);
  EXPECT_THROW(ZeroDcNoise(ZeroDcGaussianParameters{2.0, 1e-6, 0.0}, NormalStream(1)), std::invalid_argument);
}

}  // namespace
}  // namespace noise
}  // namespace imu_lab
