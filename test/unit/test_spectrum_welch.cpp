// Welch's PSD against known spectra: white noise's flat one-sided density 2 s^2 tau0 (each bin
// within its chi-squared spread), a sinusoid's power A^2 / 2 under its peak, the degrees of
// freedom and the chi-squared interval's coverage, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "imu_lab/common/config_error.h"
#include "imu_lab/spectrum/welch.h"

namespace imu_lab {
namespace spectrum {
namespace {

constexpr double kTau0S = 0.01;

// Bin densities of white noise are chi2(edf)/edf times 2 s^2 tau0; their mean over B bins has
// relative sigma sqrt(2 / (edf B)) (neighbouring Hann bins are correlated: B / 2 independent is
// the conservative count). 5 sigma of that bounds the mean; the median sits within the same.
TEST(SpectrumWelch, WhiteNoiseIsFlatAtTwiceItsVarianceTimesTau0) {
  const double sigma = 0.3;
  std::mt19937_64 generator(7);
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> values(400000);
  for (double& v : values) v = normal(generator);
  const PowerSpectrum spectrum = welch_psd(values, kTau0S, {1024});
  ASSERT_EQ(spectrum.density.size(), 513u);
  EXPECT_EQ(spectrum.segment_count, 780u);
  EXPECT_NEAR(spectrum.resolution_hz, 1.0 / (1024 * kTau0S), 1e-12);
  // Percival & Walden 1993 p. 294: Hann at 50 % overlap, nu = 36 K^2 / (19 K - 1).
  EXPECT_NEAR(spectrum.degrees_of_freedom, 36.0 * 780 * 780 / (19.0 * 780 - 1), 1e-9);
  const double expected = 2.0 * sigma * sigma * kTau0S;
  double mean = 0.0;
  int bins = 0;
  for (std::size_t bin = 1; bin + 1 < spectrum.density.size(); ++bin, ++bins) mean += spectrum.density[bin];
  mean /= bins;
  const double relative_sigma = std::sqrt(2.0 / (spectrum.degrees_of_freedom * bins / 2.0));
  EXPECT_NEAR(mean / expected, 1.0, 5.0 * relative_sigma);
  const double median = median_density(spectrum, 0.2, 49.0);
  EXPECT_NEAR(median / expected, 1.0, 5.0 * relative_sigma + 1.0 / spectrum.degrees_of_freedom);
  EXPECT_TRUE(std::isnan(median_density(spectrum, 60.0, 70.0)));
}

// A line at a bin centre: the Hann window spreads it over three bins whose summed density times
// the resolution is the line's power A^2 / 2 (the window's power normalisation), exactly.
TEST(SpectrumWelch, SinusoidPowerLiesUnderItsPeak) {
  const double amplitude = 2.0, frequency_hz = 12.5;  // bin 128 of 1024 at 100 Hz
  std::vector<double> values(8192);
  for (std::size_t k = 0; k < values.size(); ++k)
    values[k] = amplitude * std::sin(2 * M_PI * frequency_hz * k * kTau0S);
  const PowerSpectrum spectrum = welch_psd(values, kTau0S, {1024});
  double power = 0.0;
  for (std::size_t bin = 126; bin <= 130; ++bin) power += spectrum.density[bin] * spectrum.resolution_hz;
  EXPECT_NEAR(power, amplitude * amplitude / 2.0, 1e-9);
  EXPECT_LT(spectrum.density[100], 1e-20);
}

// The 90 % interval of each bin holds white noise's true density in 90 % of the bins. 40 records
// of 6 segments (nu = 10.8, a skewed chi-squared) give 40 x 127 bins; bins two apart are nearly
// independent (their power correlation is 1/36), neighbours are not, so the count's sigma is
// taken as that of 40 x 127 / 2 independent bins: sqrt(0.9 x 0.1 / 2540) = 0.006; 4 sigma bound.
TEST(SpectrumWelch, ChiSquaredIntervalCoversTheTrueDensity) {
  const double sigma = 0.5, confidence = 0.9;
  const double truth = 2.0 * sigma * sigma * kTau0S;
  std::mt19937_64 generator(11);
  std::normal_distribution<double> normal(0.0, sigma);
  int covered = 0, bins = 0, below = 0;
  for (int record = 0; record < 40; ++record) {
    std::vector<double> values(256 * 7 / 2);
    for (double& v : values) v = normal(generator);
    const PowerSpectrum spectrum = welch_psd(values, kTau0S, {256});
    ASSERT_EQ(spectrum.segment_count, 6u);
    EXPECT_TRUE(std::isnan(density_interval(spectrum, 0, confidence).lower));
    EXPECT_NEAR(bin_degrees_of_freedom(spectrum, 128), 0.5 * spectrum.degrees_of_freedom, 1e-12);
    for (std::size_t bin = 1; bin < 128; ++bin, ++bins) {
      const DensityInterval interval = density_interval(spectrum, bin, confidence);
      ASSERT_LT(interval.lower, spectrum.density[bin]);
      ASSERT_GT(interval.upper, spectrum.density[bin]);
      if (interval.lower <= truth && truth <= interval.upper) ++covered;
      if (interval.upper < truth) ++below;
    }
  }
  const double coverage = static_cast<double>(covered) / bins;
  std::printf("[welch] coverage %.4f of %d bins (interval below the truth in %d)\n", coverage, bins, below);
  EXPECT_NEAR(coverage, confidence, 4.0 * std::sqrt(confidence * (1 - confidence) / (bins / 2.0)));
  // Equal tails: as many intervals wholly below the truth as above it, 5 % each.
  EXPECT_NEAR(static_cast<double>(below) / bins, 0.5 * (1 - confidence), 4.0 * std::sqrt(0.05 * 0.95 / (bins / 2.0)));
}

TEST(SpectrumWelch, RefusesWhatHasNoSpectrum) {
  EXPECT_THROW(welch_psd(std::vector<double>(100, 1.0), kTau0S, {1024}), InputError);
  EXPECT_THROW(welch_psd(std::vector<double>(2048, 1.0), 0.0, {1024}), InputError);
  EXPECT_THROW(welch_psd(std::vector<double>(2048, 1.0), kTau0S, {4}), InputError);
  std::vector<double> with_nan(2048, 1.0);
  with_nan[7] = std::nan("");
  EXPECT_THROW(welch_psd(with_nan, kTau0S, {1024}), InputError);
}

}  // namespace
}  // namespace spectrum
}  // namespace imu_lab
