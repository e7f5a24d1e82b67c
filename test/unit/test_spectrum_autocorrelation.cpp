// The autocorrelation through the FFT against the direct sum, an AR(1) record's phi^k within
// Bartlett's spread, white noise inside its band at the stated rate, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "imu_lab/common/config_error.h"
#include "imu_lab/spectrum/autocorrelation.h"

namespace imu_lab {
namespace spectrum {
namespace {

std::vector<double> ar1(std::size_t n, double phi, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> values(n);
  double state = normal(generator) / std::sqrt(1.0 - phi * phi);
  for (double& v : values) v = state = phi * state + normal(generator);
  return values;
}

TEST(SpectrumAutocorrelation, EqualsTheDirectSum) {
  const std::vector<double> values = ar1(1000, 0.6, 3);
  const std::vector<double> r = autocorrelation(values, 50);
  double mean = 0.0;
  for (double v : values) mean += v / values.size();
  double c0 = 0.0;
  for (double v : values) c0 += (v - mean) * (v - mean);
  ASSERT_EQ(r.size(), 51u);
  EXPECT_DOUBLE_EQ(r[0], 1.0);
  for (std::size_t k = 1; k <= 50; ++k) {
    double ck = 0.0;
    for (std::size_t t = 0; t + k < values.size(); ++t) ck += (values[t] - mean) * (values[t + k] - mean);
    EXPECT_NEAR(r[k], ck / c0, 1e-12) << "lag " << k;
  }
}

// AR(1): rho(k) = phi^k; Bartlett's variance of r(k) is
// (1 / n) [(1 + phi^2)(1 - phi^(2k)) / (1 - phi^2) - 2 k phi^(2k)] (Box & Jenkins eq. 2.1.15);
// the biased estimator's mean lies below by about k rho(k) / n, far inside. 5 sigma each.
TEST(SpectrumAutocorrelation, Ar1FollowsPhiToTheLag) {
  const double phi = 0.8;
  const std::size_t n = 200000;
  const std::vector<double> r = autocorrelation(ar1(n, phi, 5), 10);
  for (int k = 1; k <= 10; ++k) {
    const double p2k = std::pow(phi, 2 * k);
    const double variance = ((1 + phi * phi) * (1 - p2k) / (1 - phi * phi) - 2 * k * p2k) / n;
    EXPECT_NEAR(r[k], std::pow(phi, k), 5.0 * std::sqrt(variance)) << "lag " << k;
  }
}

// White noise: r(k) ~ N(0, 1/n) independently, so 95 % of 2000 lags fall inside the band;
// binomial sigma sqrt(0.95 x 0.05 / 2000) = 0.0049, 4 sigma.
TEST(SpectrumAutocorrelation, WhiteNoiseStaysInsideItsBand) {
  const std::size_t n = 100000;
  const std::vector<double> r = autocorrelation(ar1(n, 0.0, 9), 2000);
  const double band = white_noise_band(n, 0.95);
  EXPECT_NEAR(band, 1.959964 / std::sqrt(100000.0), 1e-8);
  int inside = 0;
  for (std::size_t k = 1; k <= 2000; ++k) inside += std::abs(r[k]) <= band;
  std::printf("[autocorrelation] %d of 2000 lags inside the 95 %% band\n", inside);
  EXPECT_NEAR(inside / 2000.0, 0.95, 4.0 * std::sqrt(0.95 * 0.05 / 2000));
}

TEST(SpectrumAutocorrelation, Refusals) {
  EXPECT_THROW(autocorrelation(std::vector<double>(10, 1.0), 9), InputError);
  EXPECT_THROW(autocorrelation(std::vector<double>(100, 1.0), 5), InputError);
  std::vector<double> with_nan = ar1(100, 0.0, 1);
  with_nan[3] = std::nan("");
  EXPECT_THROW(autocorrelation(with_nan, 5), InputError);
  EXPECT_THROW(white_noise_band(100, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace spectrum
}  // namespace imu_lab
