// The output-step detector: the LSB of a quantised output, through the same decimal parsing and
// unit conversion as the CSV import, exactly; 0 for unquantised data and for what cannot be told.
#include "imu_lab/allan/output_step.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/io/csv_imu_import.h"
#include "impulse_test_records.h"
#include "test_emulator_paths.h"

namespace imu_lab {
namespace {

using allan::ChannelOutputStep;
using allan::OutputStepDetector;

std::vector<ChannelOutputStep> steps_of(const std::vector<std::vector<double>>& samples) {
  OutputStepDetector detector(samples.front().size());
  for (const auto& sample : samples) detector.push(sample.data());
  return detector.channels();
}

// A logger's CSV of an ADIS16405-like output (0.05 deg/s and 3.33 mg LSBs, printed as decimals),
// imported in deg/s and g: the steps in SI to the last digits, whatever the conversion's rounding.
TEST(OutputStep, DecimalOutputConvertedToSiKeepsItsStep) {
  std::mt19937_64 generator(1);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::string text = "time_s,gx,gy,gz,ax,ay,az\n";
  char row[256];
  for (int k = 0; k < 20000; ++k) {
    const long gyro[3] = {std::lround(7.0 * normal(generator)), std::lround(8.0 * normal(generator) - 3.0),
                          std::lround(9.0 * normal(generator) + 40.0)};
    const long accel[3] = {std::lround(1.2 * normal(generator)), std::lround(1.1 * normal(generator)),
                           std::lround(1.3 * normal(generator) - 307.0)};
    std::snprintf(row, sizeof row, "%.2f,%.2f,%.2f,%.2f,%.5f,%.5f,%.5f\n", k * 0.01, gyro[0] * 0.05, gyro[1] * 0.05,
                  gyro[2] * 0.05, accel[0] * 0.00333, accel[1] * 0.00333, accel[2] * 0.00333);
    text += row;
  }
  io::CsvImportOptions options;
  options.gyro_unit = io::AngularRateUnit::kDegreePerSecond;
  options.accel_unit = io::SpecificForceUnit::kStandardGravity;
  options.time_offset_ns = 1000000000;  // ROS time cannot be 0
  const auto imported = io::parse_imu_csv_text(text, options);
  ASSERT_EQ(imported.samples.size(), 20000u);
  std::vector<std::vector<double>> samples;
  for (const auto& sample : imported.samples) {
    samples.push_back({sample.angular_rate_rad_s[0], sample.angular_rate_rad_s[1], sample.angular_rate_rad_s[2],
                       sample.specific_force_m_s2[0], sample.specific_force_m_s2[1], sample.specific_force_m_s2[2]});
  }
  const auto steps = steps_of(samples);
  const double gyro_step = 0.05 * M_PI / 180.0;  // 8.7266e-4 rad/s
  const double accel_step = 0.00333 * 9.80665;   // 0.0326561 m/s^2
  for (int c = 0; c < 6; ++c) {
    const double expected = c < 3 ? gyro_step : accel_step;
    EXPECT_TRUE(steps[c].quantised) << c;
    EXPECT_NEAR(steps[c].step / expected, 1.0, 1e-12) << c;
    EXPECT_EQ(steps[c].finite_value_count, 20000);
  }
  EXPECT_GE(steps[5].largest_multiple, 307);
}

// The emulator's unquantised output (a shipped profile at rest): no step on any channel.
TEST(OutputStep, UnquantisedEmulatedDataHasNoStep) {
  const auto profile = emulator::load_sensor_profile(test::config_path("sensors/consumer_mems.yaml"));
  const auto scenario = emulator::load_scenario(test::config_path("scenarios/static.yaml"));
  emulator::ImuEmulator emulator(profile, scenario, {200.0, 0.0, 3});
  OutputStepDetector detector(6);
  for (int k = 0; k < 100000; ++k) {
    const auto sample = emulator.next();
    const double values[6] = {sample.angular_rate_rad_s[0],  sample.angular_rate_rad_s[1],
                              sample.angular_rate_rad_s[2],  sample.specific_force_m_s2[0],
                              sample.specific_force_m_s2[1], sample.specific_force_m_s2[2]};
    detector.push(values);
  }
  for (const auto& channel : detector.channels()) {
    EXPECT_FALSE(channel.quantised);
    EXPECT_EQ(channel.step, 0.0);
    EXPECT_EQ(channel.finite_value_count, 100000);
  }
}

// Emulated whole pulses: the rate is a multiple of pulse weight / interval.
TEST(OutputStep, EmulatedPulseOutputHasThePulseRateAsStep) {
  const auto record = impulse_test::emulate_static_record(600.0, 200.0, 8);
  OutputStepDetector detector(impulse_test::kChannels);
  for (std::size_t k = 0; k < record.size(); ++k) detector.push(&record.values[k * impulse_test::kChannels]);
  const auto steps = detector.channels();
  for (std::size_t c = 0; c < impulse_test::kChannels; ++c) {
    const double expected = c < 3 ? 8.7266e-4 : 0.0326561;
    EXPECT_TRUE(steps[c].quantised) << c;
    EXPECT_NEAR(steps[c].step / expected, 1.0, 1e-12) << c;
  }
}

// Values that went through single precision are not multiples within the double-precision
// tolerance: reported unquantised rather than with a wrong step.
TEST(OutputStep, SinglePrecisionValuesAreReportedUnquantised) {
  std::mt19937_64 generator(2);
  std::uniform_int_distribution<int> level(-40, 40);
  std::vector<std::vector<double>> samples;
  for (int k = 0; k < 5000; ++k) {
    const int n = level(generator);
    samples.push_back({n * 8.7266e-4, static_cast<double>(static_cast<float>(n * 8.7266e-4))});
  }
  const auto steps = steps_of(samples);
  EXPECT_TRUE(steps[0].quantised);
  EXPECT_FALSE(steps[1].quantised);
  EXPECT_EQ(steps[1].step, 0.0);
}

TEST(OutputStep, TheStepIsTheLargestCommonOneAndNeedsEvidence) {
  const double q = 0.0326561;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Multiples of 3q only: 3q is all the data can tell; a value 4q then shows q.
  auto steps = steps_of({{3 * q, 5.0, 0.0, nan}, {-6 * q, 5.0, 0.0, 2 * q}, {9 * q, 5.0, 0.0, nan}});
  EXPECT_NEAR(steps[0].step / (3 * q), 1.0, 1e-14);
  EXPECT_EQ(steps[0].largest_multiple, 3);
  EXPECT_FALSE(steps[1].quantised);  // a constant says nothing about a step
  EXPECT_FALSE(steps[2].quantised);  // nor do zeros
  EXPECT_FALSE(steps[3].quantised);  // one finite value
  EXPECT_EQ(steps[3].finite_value_count, 1);
  steps = steps_of({{3 * q}, {-6 * q}, {9 * q}, {4 * q}, {-q * 1000}});
  EXPECT_NEAR(steps[0].step / q, 1.0, 1e-14);
  EXPECT_EQ(steps[0].largest_multiple, 1000);
  // A value further than 2^17 steps from zero: the step cannot be told from rounding.
  steps = steps_of({{q}, {2 * q}, {static_cast<double>(allan::kMaxOutputStepMultiple + 1) * q}});
  EXPECT_FALSE(steps[0].quantised);
  EXPECT_EQ(steps[0].step, 0.0);
  // Multiples near 1e5 with no common factor (an accelerometer at 1 g with a 1e-5 g LSB): the
  // continued fraction of their ratio has convergents with denominators of some thousands that
  // come within 1e-9 of it; only the exact one may give the step.
  steps = steps_of({{-100609 * q}, {-100571 * q}, {-100639 * q}});
  EXPECT_TRUE(steps[0].quantised);
  EXPECT_NEAR(steps[0].step / q, 1.0, 1e-14);
  EXPECT_EQ(steps[0].largest_multiple, 100639);
  // A value a hair off a multiple (1e-6 of a step): not quantised.
  steps = steps_of({{q}, {2 * q}, {7.000001 * q}});
  EXPECT_FALSE(steps[0].quantised);
}

}  // namespace
}  // namespace imu_lab
