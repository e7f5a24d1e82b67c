// The allan tool on bad input: irregular stamps and NaN values are reported with what the policy
// did (a success under the split policy, a clear failure under --on-gap stop); an empty bag, a
// wrong topic and a truncated bag fail with a message naming the bag; a failure writes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "allan_test_support.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::CommandResult;
using imu_lab::test_support::file_exists;
using imu_lab::test_support::read_allan_summary;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;
using imu_lab::test_support::white_noise_samples;
using imu_lab::test_support::write_imu_bag;

constexpr std::int64_t kInterval_ns = 10'000'000;  // 100 Hz
constexpr std::size_t kCount = 3000;

struct ToolRun {
  std::string bag;
  std::string report;
  CommandResult result;
};

ToolRun run_allan_on(const std::vector<imu_lab::pipeline::AllanSample>& samples, const std::string& options = "") {
  ToolRun run;
  const std::string directory = scratch_directory();
  run.bag = directory + "/input.bag";
  run.report = directory + "/report";
  write_imu_bag(run.bag, samples);
  run.result = run_tool("allan", run.bag + " --no-plot --out " + run.report + " " + options);
  return run;
}

void expect_failure_naming_the_bag(const ToolRun& run, const std::string& problem) {
  EXPECT_EQ(run.result.exit_code, 1) << run.result.output;
  EXPECT_NE(run.result.output.find(run.bag), std::string::npos) << run.result.output;
  EXPECT_NE(run.result.output.find(problem), std::string::npos) << run.result.output;
  EXPECT_FALSE(file_exists(run.report)) << "a failed run must leave no output";
}

TEST(AllanToolBadInput, AGapSplitsAndPoolsUnderTheDefaultPolicyAndStopsUnderStop) {
  auto samples = white_noise_samples(kCount, kInterval_ns, 1);
  for (std::size_t i = 2000; i < kCount; ++i) samples[i].stamp_ns += 50 * kInterval_ns;  // 0.5 s hole
  const ToolRun pooled = run_allan_on(samples);
  ASSERT_EQ(pooled.result.exit_code, 0) << pooled.result.output;
  EXPECT_NE(pooled.result.output.find("1 gaps"), std::string::npos) << pooled.result.output;
  const YAML::Node summary = read_allan_summary(pooled.report);
  EXPECT_EQ(summary["gaps"]["count"].as<int>(), 1);
  EXPECT_NEAR(summary["gap_time_s"].as<double>(), 0.5, 1e-9);
  EXPECT_NE(summary["gaps"]["action"].as<std::string>().find("pooled"), std::string::npos);
  EXPECT_EQ(summary["channels"]["gyro_x"]["segments"].as<int>(), 2);
  EXPECT_EQ(summary["first_stamp_events"][0]["sample_index"].as<int>(), 2000);

  expect_failure_naming_the_bag(run_allan_on(samples, "--on-gap stop"), "gap");
}

TEST(AllanToolBadInput, DuplicateStampsAreDroppedAndCounted) {
  auto samples = white_noise_samples(kCount, kInterval_ns, 2);
  for (std::size_t i : {1500u, 1501u, 2500u}) samples.insert(samples.begin() + i, samples[i - 1]);
  const ToolRun run = run_allan_on(samples);
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const YAML::Node summary = read_allan_summary(run.report);
  EXPECT_EQ(summary["duplicates"]["count"].as<int>(), 3);
  EXPECT_EQ(summary["duplicates"]["action"].as<std::string>(), "samples dropped");
  EXPECT_EQ(summary["samples"].as<std::size_t>(), kCount + 3);
  EXPECT_EQ(summary["accepted_samples"].as<std::size_t>(), kCount);

  expect_failure_naming_the_bag(run_allan_on(samples, "--on-gap stop"), "duplicate");
}

TEST(AllanToolBadInput, UnorderedStampsAreDroppedAndCounted) {
  auto samples = white_noise_samples(kCount, kInterval_ns, 3);
  std::swap(samples[1800], samples[1801]);
  const ToolRun run = run_allan_on(samples);
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const YAML::Node summary = read_allan_summary(run.report);
  EXPECT_EQ(summary["out_of_order"]["count"].as<int>(), 1);
  // The later sample arrives first, two intervals after its predecessor: a gap, then the earlier
  // one is out of order and dropped.
  EXPECT_EQ(summary["gaps"]["count"].as<int>(), 1);
  EXPECT_EQ(summary["first_stamp_events"][0]["kind"].as<std::string>(), "gap");
  EXPECT_EQ(summary["first_stamp_events"][1]["kind"].as<std::string>(), "out_of_order");
  EXPECT_EQ(summary["first_stamp_events"][1]["sample_index"].as<int>(), 1801);
  EXPECT_NE(run.result.output.find("1 out-of-order"), std::string::npos) << run.result.output;
}

TEST(AllanToolBadInput, NanValuesAreExcludedFromTheirChannelOnly) {
  auto samples = white_noise_samples(kCount, kInterval_ns, 4);
  for (std::size_t i : {1200u, 2200u}) samples[i].values[1] = std::numeric_limits<double>::quiet_NaN();
  const ToolRun run = run_allan_on(samples);
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const YAML::Node summary = read_allan_summary(run.report);
  EXPECT_EQ(summary["non_finite_values"]["count"].as<int>(), 2);
  EXPECT_EQ(summary["channels"]["gyro_y"]["non_finite_samples"].as<int>(), 2);
  EXPECT_EQ(summary["channels"]["gyro_y"]["segments"].as<int>(), 3);
  EXPECT_EQ(summary["channels"]["gyro_x"]["segments"].as<int>(), 1);
  EXPECT_TRUE(std::isfinite(summary["channels"]["gyro_y"]["min_oadev_rad_s"].as<double>()));
  EXPECT_NE(run.result.output.find("2 NaN/Inf"), std::string::npos) << run.result.output;
}

TEST(AllanToolBadInput, EmptyBagFailsNamingIt) {
  const std::string directory = scratch_directory();
  const std::string bag = directory + "/empty.bag";
  write_imu_bag(bag, {});
  const auto result = run_tool("allan", bag + " --out " + directory + "/report");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(bag), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("no sensor_msgs/Imu topic"), std::string::npos) << result.output;
  EXPECT_FALSE(file_exists(directory + "/report"));
}

TEST(AllanToolBadInput, TooFewMessagesFailNamingTheTopic) {
  const ToolRun run = run_allan_on(white_noise_samples(5, kInterval_ns, 5));
  expect_failure_naming_the_bag(run, "has 5 messages");
}

TEST(AllanToolBadInput, WrongTopicFailsListingTheTopicsThatExist) {
  const ToolRun run = run_allan_on(white_noise_samples(100, kInterval_ns, 6), "--topic /imu/nothing");
  expect_failure_naming_the_bag(run, "/imu/nothing");
  EXPECT_NE(run.result.output.find("/imu/raw (sensor_msgs/Imu, 100 messages)"), std::string::npos) << run.result.output;
}

TEST(AllanToolBadInput, TruncatedBagFailsNamingItAndWritesNothing) {
  const std::string directory = scratch_directory();
  const std::string whole = directory + "/whole.bag";
  write_imu_bag(whole, white_noise_samples(kCount, kInterval_ns, 7));
  const std::string bytes = imu_lab::test_support::read_file(whole);
  for (const double fraction : {0.5, 0.97}) {
    const std::string bag = directory + "/truncated_" + std::to_string(static_cast<int>(100 * fraction)) + ".bag";
    std::ofstream(bag, std::ios::binary) << bytes.substr(0, static_cast<std::size_t>(bytes.size() * fraction));
    const std::string report = directory + "/report";
    const auto result = run_tool("allan", bag + " --out " + report);
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find(bag), std::string::npos) << result.output;
    EXPECT_FALSE(file_exists(report));
  }
}

TEST(AllanToolBadInput, BadOptionIsAConfigurationError) {
  const ToolRun run = run_allan_on(white_noise_samples(2000, kInterval_ns, 8), "--confidence 1.5");
  EXPECT_EQ(run.result.exit_code, 2) << run.result.output;
  EXPECT_NE(run.result.output.find("confidence"), std::string::npos) << run.result.output;
  EXPECT_FALSE(file_exists(run.report));
}

TEST(AllanToolBadInput, UnknownZeroDcTermIsAConfigurationErrorNamingIt) {
  const ToolRun run =
      run_allan_on(white_noise_samples(2000, kInterval_ns, 9), "--zero-dc-terms high_pass_white,markov");
  EXPECT_EQ(run.result.exit_code, 2) << run.result.output;
  EXPECT_NE(run.result.output.find("markov"), std::string::npos) << run.result.output;
  EXPECT_FALSE(file_exists(run.report));
}

}  // namespace
