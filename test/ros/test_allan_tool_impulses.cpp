// The allan tool's impulse screen as a user meets it: a knock in a bag is printed with its stamps
// and listed in allan_summary.yaml, and the run is split there (a gap to the engine, not one of
// the input's); --no-impulse-screen keeps it in;
// --impulse-threshold decides; the output steps are in the summary.
#include <gtest/gtest.h>

#include <cmath>

#include "allan_test_support.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::add_knock;
using imu_lab::test_support::read_allan_summary;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;
using imu_lab::test_support::white_noise_samples;
using imu_lab::test_support::write_imu_bag;

constexpr std::int64_t kInterval_ns = 5'000'000;  // 200 Hz
constexpr std::size_t kCount = 12000;             // 60 s
constexpr std::size_t kKnockSample = 6000;        // 30 s from the first stamp

// White noise with a knock at 30 s (add_knock).
std::string knocked_bag() {
  auto samples = white_noise_samples(kCount, kInterval_ns, 3);
  add_knock(samples, kKnockSample);
  const std::string bag = scratch_directory() + "/knocked.bag";
  write_imu_bag(bag, samples);
  return bag;
}

TEST(AllanToolImpulses, AKnockIsPrintedListedAndSplitsTheRun) {
  const std::string bag = knocked_bag();
  const std::string report = scratch_directory() + "/report";
  const auto run = run_tool("allan", bag + " --no-plot --no-identify --out " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("impulse screen (threshold 12 scales): 1 events"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("samples left out of the curves; the run is split at each"), std::string::npos)
      << run.output;
  // The stamps are regular: the hole the screen left is no irregularity of the input.
  EXPECT_EQ(run.output.find("irregular input"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("event 1: onset 30.00 s from the start"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("output steps"), std::string::npos) << run.output;
  const YAML::Node summary = read_allan_summary(report);
  const YAML::Node screen = summary["impulse_screen"];
  EXPECT_TRUE(screen["enabled"].as<bool>());
  EXPECT_EQ(screen["events"]["count"].as<int>(), 1);
  ASSERT_EQ(screen["listed_events"].size(), 1u);
  const YAML::Node event = screen["listed_events"][0];
  EXPECT_NEAR(event["onset_from_start_s"].as<double>(), 30.0, 1e-9);
  EXPECT_EQ(event["onset_stamp_ns"].as<std::int64_t>(), 1'000'000'000'000'000'000LL + 6000 * kInterval_ns);
  EXPECT_EQ(event["peak_channel"].as<std::string>(), "accel_z");
  EXPECT_GT(event["peak_sigma"].as<double>(), 100.0);
  EXPECT_NEAR(event["window_from_start_s"][0].as<double>(), 29.75, 1e-9);
  EXPECT_GE(event["window_from_start_s"][1].as<double>(), 31.0);
  EXPECT_EQ(screen["dropped_samples"].as<int>(), event["dropped_samples"].as<int>());
  EXPECT_EQ(summary["samples"].as<int>() + screen["dropped_samples"].as<int>(), static_cast<int>(kCount));
  // The hole is a gap to the engine: two segments, on every channel.
  EXPECT_EQ(summary["gaps"]["count"].as<int>(), 1);
  EXPECT_EQ(summary["gaps_made_by_impulse_screen"].as<int>(), 1);
  EXPECT_EQ(summary["channels"]["gyro_x"]["segments"].as<int>(), 2);
  EXPECT_EQ(summary["channels"]["accel_z"]["segments"].as<int>(), 2);
  // White noise in double precision: no step.
  EXPECT_EQ(summary["channels"]["accel_z"]["output_step_m_s2"].as<double>(), 0.0);
  EXPECT_EQ(summary["channels"]["gyro_x"]["output_step_rad_s"].as<double>(), 0.0);
}

TEST(AllanToolImpulses, OptionsTurnTheScreenOffOrMoveItsThreshold) {
  const std::string bag = knocked_bag();
  const std::string off = scratch_directory() + "/off";
  auto run = run_tool("allan", bag + " --no-plot --no-identify --no-impulse-screen --out " + off);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("impulse screen off"), std::string::npos) << run.output;
  YAML::Node summary = read_allan_summary(off);
  EXPECT_FALSE(summary["impulse_screen"]["enabled"].as<bool>());
  EXPECT_EQ(summary["samples"].as<int>(), static_cast<int>(kCount));
  EXPECT_EQ(summary["channels"]["accel_z"]["segments"].as<int>(), 1);

  const std::string high = scratch_directory() + "/high";
  run = run_tool("allan", bag + " --no-plot --no-identify --impulse-threshold 1000 --out " + high);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  summary = read_allan_summary(high);
  EXPECT_EQ(summary["impulse_screen"]["threshold_sigma"].as<double>(), 1000.0);
  EXPECT_EQ(summary["impulse_screen"]["events"]["count"].as<int>(), 0);

  run = run_tool("allan", bag + " --no-plot --impulse-threshold 2 --out " + scratch_directory() + "/bad");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("--impulse-threshold"), std::string::npos) << run.output;
}

}  // namespace
