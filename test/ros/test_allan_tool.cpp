// The allan tool, run as a user runs it: its CSVs are the streaming engine's curves on the same
// samples, for rate and increment input; real bags with uneven stamps go through and their sample
// period and jitter are reported.
#include <gtest/gtest.h>

#include <cstdio>

#include "allan_test_support.h"
#include "imu_lab/allan/streaming_allan.h"
#include "imu_lab/io/stability_table.h"
#include "imu_lab/ros_io/bag/allan_report.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "ros_test_support.h"

#ifndef IMU_LAB_CONFIG_DIR
#define IMU_LAB_CONFIG_DIR "config"
#endif
#ifndef IMU_LAB_REFERENCE_DIR
#define IMU_LAB_REFERENCE_DIR "../shared/reference"
#endif

namespace {

using imu_lab::allan::Statistic;
using imu_lab::pipeline::AllanInput;
using imu_lab::test_support::file_exists;
using imu_lab::test_support::read_allan_summary;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;

// One emulated bag (tactical MEMS at rest, 90 s at 200 Hz) for every test of this file.
class AllanTool : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = scratch_directory();
    bag_ = directory_ + "/tactical.bag";
    const auto made = run_tool("emulate", "--profile " + std::string(IMU_LAB_CONFIG_DIR) +
                                              "/sensors/tactical_mems.yaml --duration-s 90 --rate-hz 200 --seed 5 "
                                              "--no-truth --out " +
                                              bag_);
    ASSERT_EQ(made.exit_code, 0) << made.output;
  }

  // The engine fed what the bag reader gives, with the tool's default options.
  static imu_lab::allan::StreamingSnapshot engine_on_bag(AllanInput input, const std::string& topic) {
    imu_lab::allan::StreamingOptions options;
    options.input_kind = imu_lab::pipeline::engine_input_kind(input);
    imu_lab::allan::StreamingAllan engine(options);
    const auto push = [&](const imu_lab::pipeline::AllanSample& sample) {
      engine.push(sample.stamp_ns, sample.values.data(), sample.values.size());
    };
    if (input == AllanInput::kRate) {
      imu_lab::ros_io::for_each_imu(bag_, topic,
                                    [&](const auto& record) { push(imu_lab::pipeline::to_allan_sample(record)); });
    } else {
      imu_lab::ros_io::for_each_increment(
          bag_, topic, [&](const auto& record) { push(imu_lab::pipeline::to_allan_sample(record)); });
    }
    return engine.snapshot();
  }

  // Every CSV the tool wrote equals the engine's curves (the CSV keeps all 17 digits).
  static void expect_csvs_equal_engine(const std::string& report, const imu_lab::allan::StreamingSnapshot& expected) {
    for (const Statistic statistic : imu_lab::allan::kStreamingStatistics) {
      const std::string path = report + "/" + imu_lab::allan::statistic_name(statistic) + ".csv";
      ASSERT_TRUE(file_exists(path)) << path;
      const auto written = imu_lab::io::parse_stability_csv(read_file(path));
      const auto wanted = imu_lab::ros_io::channel_curves(expected, statistic);
      ASSERT_EQ(written.size(), wanted.size()) << path;
      for (std::size_t c = 0; c < wanted.size(); ++c) {
        EXPECT_EQ(written[c].name, wanted[c].name);
        EXPECT_EQ(written[c].unit, wanted[c].unit);
        ASSERT_EQ(written[c].points.size(), wanted[c].points.size()) << path << " " << wanted[c].name;
        ASSERT_GT(wanted[c].points.size(), 10u);
        for (std::size_t i = 0; i < wanted[c].points.size(); ++i) {
          EXPECT_EQ(written[c].points[i].averaging_factor, wanted[c].points[i].averaging_factor);
          EXPECT_EQ(written[c].points[i].deviation, wanted[c].points[i].deviation) << path << " " << wanted[c].name;
          EXPECT_EQ(written[c].points[i].deviation_upper, wanted[c].points[i].deviation_upper);
          EXPECT_EQ(written[c].points[i].term_count, wanted[c].points[i].term_count);
        }
      }
    }
  }

  static std::string directory_;
  static std::string bag_;
};

std::string AllanTool::directory_;
std::string AllanTool::bag_;

TEST_F(AllanTool, CsvsEqualTheStreamingEngineOnTheSameSamples) {
  const std::string report = scratch_directory() + "/report";
  const auto run = run_tool("allan", bag_ + " --topic /imu/raw --out " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  expect_csvs_equal_engine(report, engine_on_bag(AllanInput::kRate, "/imu/raw"));

  const YAML::Node summary = read_allan_summary(report);
  EXPECT_EQ(summary["bag"].as<std::string>(), bag_);
  EXPECT_EQ(summary["topic"].as<std::string>(), "/imu/raw");
  EXPECT_EQ(summary["samples"].as<long long>(), 18000);
  EXPECT_NEAR(summary["tau0_s"].as<double>(), 0.005, 1e-12);
  EXPECT_LT(summary["interval_max_deviation_s"].as<double>(), 1e-8);  // integer-nanosecond stamps
  EXPECT_EQ(summary["gaps"]["count"].as<long long>(), 0);
  EXPECT_NEAR(summary["channels"]["accel_z"]["offset_m_s2"].as<double>(), 9.8, 0.1);
  EXPECT_GT(summary["channels"]["gyro_x"]["min_oadev_rad_s"].as<double>(), 0.0);
  EXPECT_GT(summary["channels"]["gyro_x"]["min_oadev_tau_s"].as<double>(), 0.005);
  if (file_exists("/usr/bin/python3")) {
    EXPECT_TRUE(file_exists(report + "/allan.png")) << run.output;
  }
  // The report is staged and moved in whole: no staging path reaches the user.
  EXPECT_EQ(run.output.find(".staging"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("plot_allan:"), std::string::npos) << run.output;
}

TEST_F(AllanTool, IncrementInputGivesTheEngineCurvesInRateUnits) {
  const std::string report = scratch_directory() + "/report";
  const auto run = run_tool("allan", bag_ + " --input increment --no-plot --out " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto increments = engine_on_bag(AllanInput::kIncrement, "/imu/increment");
  expect_csvs_equal_engine(report, increments);
  EXPECT_EQ(read_allan_summary(report)["topic"].as<std::string>(), "/imu/increment");
  // The emulator's increments are its rates times the interval: the same curves in rad/s.
  const auto rates = engine_on_bag(AllanInput::kRate, "/imu/raw");
  const auto& a = rates.curve(Statistic::kOverlappingAllan, 0);
  const auto& b = increments.curve(Statistic::kOverlappingAllan, 0);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(b[i].deviation / a[i].deviation, 1.0, 1e-6);
  EXPECT_FALSE(file_exists(report + "/allan.png"));
}

TEST_F(AllanTool, ProgressBarOnRequestWithAnEta) {
  const std::string report = scratch_directory() + "/report";
  const auto run = run_tool("allan", bag_ + " --topic /imu/raw --no-plot --progress --out " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("100.0 % 18000/18000 messages, ETA"), std::string::npos) << run.output;
}

TEST(AllanToolRealBags, BothReferenceBagsGoThroughWithTheirSamplePeriodAndJitterReported) {
  for (const char* name : {"phidgets_imu_upside_down.bag", "sparkfun_razor.bag"}) {
    const std::string bag = std::string(IMU_LAB_REFERENCE_DIR) + "/real_bags/" + name;
    const std::string report = scratch_directory() + "/report";
    const auto run = run_tool("allan", bag + " --no-plot --out " + report);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("tau0"), std::string::npos) << run.output;
    const YAML::Node summary = read_allan_summary(report);
    const double tau0_s = summary["tau0_s"].as<double>();
    const double rms_s = summary["interval_rms_deviation_s"].as<double>();
    const double max_s = summary["interval_max_deviation_s"].as<double>();
    std::printf(
        "%s: %lld samples, tau0 %.6g s (%.4g Hz), interval jitter rms %.3g s, max %.3g s; %lld gaps, "
        "%lld duplicates, %lld out of order\n",
        name, summary["samples"].as<long long>(), tau0_s, 1.0 / tau0_s, rms_s, max_s,
        summary["gaps"]["count"].as<long long>(), summary["duplicates"]["count"].as<long long>(),
        summary["out_of_order"]["count"].as<long long>());
    EXPECT_GT(tau0_s, 1e-4) << name;
    EXPECT_LT(tau0_s, 0.1) << name;
    EXPECT_GT(rms_s, 0.0) << name << ": real stamps jitter";
    EXPECT_GE(max_s, rms_s) << name;
    EXPECT_TRUE(file_exists(report + "/oadev.csv")) << name;
  }
}

}  // namespace
