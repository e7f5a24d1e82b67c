// allan --remove-warm-up, run as a user runs it on an emulated bag with a self-heating warm-up
// (tactical_mems in config/scenarios/static_warm_up.yaml): warm_up.yaml holds the model the core
// fit (thermal/warm_up_transient.h) finds on the bag's own samples, the curves are the engine's on
// the samples with that transient subtracted, and a bad block length is a usage error.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "allan_test_support.h"
#include "imu_lab/allan/streaming_allan.h"
#include "imu_lab/io/stability_table.h"
#include "imu_lab/pipeline/allan_warm_up.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "ros_test_support.h"

#ifndef IMU_LAB_CONFIG_DIR
#define IMU_LAB_CONFIG_DIR "config"
#endif

namespace {

using imu_lab::test_support::file_exists;
using imu_lab::test_support::read_allan_summary;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;

TEST(AllanToolWarmUp, RemovesTheModelTheCoreFitsAndReportsIt) {
  const std::string directory = scratch_directory();
  const std::string bag = directory + "/warm.bag";
  const auto made = run_tool("emulate", "--profile " + std::string(IMU_LAB_CONFIG_DIR) +
                                            "/sensors/tactical_mems.yaml --scenario " + IMU_LAB_CONFIG_DIR +
                                            "/scenarios/static_warm_up.yaml --duration-s 3600 --rate-hz 10 "
                                            "--seed 3 --no-truth --no-increments --out " +
                                            bag);
  ASSERT_EQ(made.exit_code, 0) << made.output;
  const std::string report = directory + "/report";
  const auto run = run_tool("allan", bag + " --remove-warm-up --no-plot --no-identify --out " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("warm-up removed"), std::string::npos) << run.output;
  EXPECT_TRUE(read_allan_summary(report)["warm_up_removed"].IsDefined());

  // The core on the same samples: block means, the fit, the removal, the engine.
  imu_lab::thermal::WarmUpBlockMeans blocks(imu_lab::pipeline::kAllanChannelCount, 1.0);
  std::vector<imu_lab::pipeline::AllanSample> samples;
  imu_lab::ros_io::for_each_imu(bag, "/imu/raw", [&](const auto& record) {
    samples.push_back(imu_lab::pipeline::to_allan_sample(record));
    blocks.push(samples.back().stamp_ns, samples.back().values.data());
  });
  imu_lab::pipeline::AllanWarmUpOptions options;
  options.enabled = true;
  const auto warm_up = imu_lab::pipeline::fit_allan_warm_up(blocks, options);
  const YAML::Node written = YAML::LoadFile(report + "/warm_up.yaml");
  for (std::size_t c = 0; c < imu_lab::pipeline::kAllanChannelCount; ++c) {
    const YAML::Node channel = written["channels"][imu_lab::pipeline::kAllanChannelNames[c]];
    ASSERT_TRUE(warm_up.channels[c].fit.has_value()) << c;
    const auto& fit = *warm_up.channels[c].fit;
    ASSERT_EQ(channel["terms"].size(), fit.terms.size()) << c;
    for (std::size_t k = 0; k < fit.terms.size(); ++k) {
      EXPECT_DOUBLE_EQ(channel["terms"][k]["time_constant_s"].as<double>(), fit.terms[k].time_constant_s);
    }
  }
  // The accelerometers' warm-up (about 1.5 mg over 4 degC) stands out of their noise: the F-test
  // keeps it on at least one of them in this hour.
  std::size_t accelerometer_terms = 0;
  for (const char* name : {"accel_x", "accel_y", "accel_z"})
    accelerometer_terms += written["channels"][name]["terms"].size();
  EXPECT_GE(accelerometer_terms, 1u);

  imu_lab::allan::StreamingAllan engine{imu_lab::allan::StreamingOptions()};
  for (auto sample : samples) {
    warm_up.remove_from(sample);
    engine.push(sample.stamp_ns, sample.values.data(), sample.values.size());
  }
  const auto expected = engine.snapshot();
  const auto curves = imu_lab::io::parse_stability_csv(read_file(report + "/oadev.csv"));
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const auto& wanted = expected.curve(imu_lab::allan::Statistic::kOverlappingAllan, c);
    ASSERT_EQ(curves[c].points.size(), wanted.size());
    for (std::size_t i = 0; i < wanted.size(); ++i) {
      EXPECT_NEAR(curves[c].points[i].deviation, wanted[i].deviation, 1e-12 * wanted[i].deviation);
    }
  }

  const auto refused = run_tool("allan", bag + " --remove-warm-up --warm-up-block-s 0 --out " + report);
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("--warm-up-block-s"), std::string::npos) << refused.output;
}

}  // namespace
