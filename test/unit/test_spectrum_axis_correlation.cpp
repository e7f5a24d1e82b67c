// The axes' correlation matrix against triads of known correlation: Fisher's interval holds the
// truth at its stated rate, the matrix of white noise is the same after averaging, block means
// that are correlated in time are flagged, and the refusals name the factor or the axis. Then the
// spectrum analysis of a whole record (spectrum_report.h): its files and its refusal of gaps.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <Eigen/Cholesky>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/spectrum/axis_correlation.h"
#include "imu_lab/spectrum/spectrum_report.h"

namespace imu_lab {
namespace spectrum {
namespace {

Eigen::Matrix3d truth_matrix() {
  Eigen::Matrix3d r;
  r << 1.0, 0.6, -0.3, 0.6, 1.0, 0.2, -0.3, 0.2, 1.0;
  return r;
}

// Unit-variance white triad with correlation `r`, then scaled per axis (scales do not change it).
std::vector<Eigen::Vector3d> correlated_white(std::size_t n, const Eigen::Matrix3d& r, std::mt19937_64& generator) {
  const Eigen::Matrix3d factor = r.llt().matrixL();
  std::normal_distribution<double> normal(0.0, 1.0);
  const Eigen::Vector3d scale(1e-4, 3e-4, 2e-4);
  std::vector<Eigen::Vector3d> samples(n);
  for (auto& s : samples)
    s = scale.cwiseProduct(factor * Eigen::Vector3d(normal(generator), normal(generator), normal(generator)));
  return samples;
}

// 2000 records of 20 samples: the 90 % interval of each pair holds the truth in 90 % of them.
// The three pairs of a record are not independent, so the count's sigma is taken as that of
// 2000 checks, not 6000: sqrt(0.9 x 0.1 / 2000) = 0.0067; 4 sigma. (Fisher's 1 / sqrt(n - 3)
// replaced by 1 / sqrt(n + 3) drops the coverage to about 0.84.)
TEST(SpectrumAxisCorrelation, FisherIntervalHoldsTheTruthAtItsRate) {
  std::mt19937_64 generator(21);
  const Eigen::Matrix3d truth = truth_matrix();
  int covered = 0, checks = 0;
  for (int record = 0; record < 2000; ++record) {
    const AxisCorrelation c = axis_correlation(correlated_white(20, truth, generator), 0.01, 1, 0.9);
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(c.correlation(a, a), 1.0);
      for (int b = a + 1; b < 3; ++b, ++checks) {
        ASSERT_EQ(c.correlation(a, b), c.correlation(b, a));
        ASSERT_LT(c.lower(a, b), c.correlation(a, b));
        ASSERT_GT(c.upper(a, b), c.correlation(a, b));
        covered += c.lower(a, b) <= truth(a, b) && truth(a, b) <= c.upper(a, b);
      }
    }
  }
  const double coverage = static_cast<double>(covered) / checks;
  std::printf("[axis correlation] coverage %.4f of %d pairs\n", coverage, checks);
  EXPECT_NEAR(coverage, 0.9, 4.0 * std::sqrt(0.9 * 0.1 / 2000));
}

// One long record: at tau0 and after averaging over 10 and 100 samples the 99.9 % interval holds
// the truth (one chance in 1000 per pair of a false failure), and the block means pass the
// independence check.
TEST(SpectrumAxisCorrelation, WhiteNoiseKeepsItsMatrixUnderAveraging) {
  std::mt19937_64 generator(22);
  const Eigen::Matrix3d truth = truth_matrix();
  const std::vector<Eigen::Vector3d> samples = correlated_white(400000, truth, generator);
  for (std::size_t factor : {1, 10, 100}) {
    const AxisCorrelation c = axis_correlation(samples, 0.005, factor, 0.999);
    EXPECT_EQ(c.block_count, 400000 / factor);
    EXPECT_DOUBLE_EQ(c.averaging_time_s, 0.005 * factor);
    for (int a = 0; a < 3; ++a) {
      for (int b = a + 1; b < 3; ++b) {
        std::printf("[axis correlation] m %zu pair %d%d: %.4f in [%.4f, %.4f], truth %.1f\n", factor, a, b,
                    c.correlation(a, b), c.lower(a, b), c.upper(a, b), truth(a, b));
        EXPECT_LE(c.lower(a, b), truth(a, b)) << "m " << factor;
        EXPECT_GE(c.upper(a, b), truth(a, b)) << "m " << factor;
      }
    }
    EXPECT_TRUE(c.blocks_look_independent()) << c.block_lag1_autocorrelation.transpose();
  }
}

// A random walk on one axis: its block means follow each other, so the interval's assumption fails
// and the result says so.
TEST(SpectrumAxisCorrelation, BlockMeansCorrelatedInTimeAreFlagged) {
  std::mt19937_64 generator(23);
  std::vector<Eigen::Vector3d> samples = correlated_white(20000, Eigen::Matrix3d::Identity(), generator);
  std::normal_distribution<double> normal(0.0, 1e-5);
  double walk = 0.0;
  for (auto& s : samples) s.y() += walk += normal(generator);
  const AxisCorrelation c = axis_correlation(samples, 0.01, 10, 0.95);
  EXPECT_GT(c.block_lag1_autocorrelation.y(), 0.9);
  EXPECT_FALSE(c.blocks_look_independent());
}

// Issue 46: on a real MEMS record every line printed an interval and then "interval too narrow".
// Axes that follow themselves in time (AR(1), phi = 0.9, innovations correlated as truth_matrix)
// keep the cross-correlation of their innovations but carry about (1 - phi^2) / (1 + phi^2) of
// the independent values: Fisher's interval on n held the truth in about 40 % of the records.
// With the effective count it holds it at about its stated 90 % (the cut-off at n / 5 lags and the
// tapered autocorrelation leave it a little short).
TEST(SpectrumAxisCorrelation, IntervalHoldsTheTruthForBlockMeansCorrelatedInTime) {
  std::mt19937_64 generator(24);
  const Eigen::Matrix3d truth = truth_matrix();
  const double phi = 0.9;
  int covered = 0, checks = 0;
  for (int record = 0; record < 400; ++record) {
    std::vector<Eigen::Vector3d> samples = correlated_white(2000, truth, generator);
    for (std::size_t k = 1; k < samples.size(); ++k) samples[k] += phi * samples[k - 1];
    const AxisCorrelation c = axis_correlation(samples, 0.01, 1, 0.9);
    EXPECT_FALSE(c.blocks_look_independent());
    for (int a = 0; a < 3; ++a) {
      for (int b = a + 1; b < 3; ++b, ++checks) {
        EXPECT_LT(c.effective_block_count(a, b), 0.2 * 2000);
        covered += c.lower(a, b) <= truth(a, b) && truth(a, b) <= c.upper(a, b);
      }
    }
  }
  const double coverage = static_cast<double>(covered) / checks;
  std::printf("[axis correlation] AR(1) 0.9: coverage %.4f of %d pairs\n", coverage, checks);
  EXPECT_NEAR(coverage, 0.9, 0.04);
}

TEST(SpectrumAxisCorrelation, RefusalsNameTheFactorOrTheAxis) {
  std::mt19937_64 generator(24);
  std::vector<Eigen::Vector3d> samples = correlated_white(95, truth_matrix(), generator);
  try {
    axis_correlation(samples, 0.01, 10, 0.95);
    ADD_FAILURE() << "9 blocks accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("averaging factor 10 leaves 9 blocks"), std::string::npos) << e.what();
  }
  EXPECT_THROW(axis_correlation(samples, 0.01, 0, 0.95), InputError);
  EXPECT_THROW(axis_correlation(samples, 0.01, 1, 1.5), std::invalid_argument);
  for (auto& s : samples) s.z() = 0.25;
  try {
    axis_correlation(samples, 0.01, 1, 0.95);
    ADD_FAILURE() << "a constant axis accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("axis z does not vary"), std::string::npos) << e.what();
  }
}

std::vector<io::ImuRecord> white_record(std::size_t n, double tau0_s) {
  std::mt19937_64 generator(25);
  const std::vector<Eigen::Vector3d> gyro = correlated_white(n, truth_matrix(), generator);
  const std::vector<Eigen::Vector3d> accelerometer = correlated_white(n, Eigen::Matrix3d::Identity(), generator);
  std::vector<io::ImuRecord> samples(n);
  for (std::size_t k = 0; k < n; ++k) {
    samples[k] = io::make_imu_record(1.7e9 + static_cast<double>(k) * tau0_s, gyro[k],
                                     accelerometer[k] + Eigen::Vector3d(0, 0, 9.8));
  }
  return samples;
}

TEST(SpectrumAnalysis, FilesHoldEveryChannelAndTheMatrices) {
  SpectrumOptions options;
  options.welch.segment_length = 256;
  options.max_lag_s = 1.0;
  const SpectrumAnalysis analysis = analyse_spectra(white_record(20000, 0.01), options);
  EXPECT_NEAR(analysis.tau0_s, 0.01, 1e-9);
  ASSERT_EQ(analysis.channels.size(), 6u);
  EXPECT_EQ(analysis.channels[3].name, "accelerometer_x");
  const std::string psd = psd_csv(analysis);
  EXPECT_EQ(psd.substr(0, psd.find(',', psd.find(',') + 1)), "frequency_hz,degrees_of_freedom");
  EXPECT_NE(psd.find("gyro_x_psd_rad2_s2_per_hz,gyro_x_psd_rad2_s2_per_hz_lower"), std::string::npos);
  EXPECT_NE(psd.find("accelerometer_z_psd_m2_s4_per_hz_upper\n"), std::string::npos);
  EXPECT_EQ(std::count(psd.begin(), psd.end(), '\n'), 1 + 128);  // header, bins 1 .. 128
  const std::string acf = autocorrelation_csv(analysis);
  EXPECT_EQ(std::count(acf.begin(), acf.end(), '\n'), 1 + 101);  // header, lags 0 .. 1 s
  const YAML::Node yaml = YAML::Load(correlation_yaml(analysis, "test.bag"));
  EXPECT_EQ(yaml["welch"]["segment_count"].as<int>(), 155);
  const YAML::Node gyro = yaml["axis_correlation"]["gyro"];
  ASSERT_EQ(gyro.size(), 3u);
  EXPECT_EQ(gyro[2]["averaging_factor"].as<int>(), 100);
  EXPECT_EQ(gyro[0]["correlation"][0][1].as<double>(), analysis.triads[0].by_factor[0].correlation(0, 1));
  EXPECT_LT(gyro[0]["lower"][0][1].as<double>(), 0.6);
  EXPECT_GT(gyro[0]["upper"][0][1].as<double>(), 0.6);
  EXPECT_NE(spectrum_summary(analysis).find("gyro axis correlation at 0.01 s: xy +0."), std::string::npos)
      << spectrum_summary(analysis);
}

TEST(SpectrumAnalysis, RefusesAGapNamingItsTime) {
  std::vector<io::ImuRecord> samples = white_record(20000, 0.01);
  samples.erase(samples.begin() + 1500, samples.begin() + 1510);
  try {
    analyse_spectra(samples, SpectrumOptions());
    ADD_FAILURE() << "a gap accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("interval 0.11 s at 15.1 s after the first stamp"), std::string::npos)
        << e.what();
  }
  SpectrumOptions too_long;
  too_long.averaging_factors = {1, 5000};
  try {
    analyse_spectra(white_record(20000, 0.01), too_long);
    ADD_FAILURE() << "4 blocks accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gyro: axis correlation: averaging factor 5000"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace spectrum
}  // namespace imu_lab
