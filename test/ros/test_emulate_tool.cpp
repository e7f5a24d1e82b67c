// The emulate tool, run as a user runs it.
#include <gtest/gtest.h>

#include <fstream>

#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "ros_test_support.h"

#ifndef IMU_LAB_CONFIG_DIR
#define IMU_LAB_CONFIG_DIR "config"
#endif

namespace {

using imu_lab::test_support::file_exists;
using imu_lab::test_support::list_directory;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;

const std::string kProfile = std::string(IMU_LAB_CONFIG_DIR) + "/sensors/tactical_mems.yaml";
const std::string kScenario = std::string(IMU_LAB_CONFIG_DIR) + "/scenarios/static.yaml";

std::string emulate_arguments(const std::string& out, int seed) {
  return "--profile " + kProfile + " --scenario " + kScenario + " --duration-s 20 --rate-hz 200 --seed " +
         std::to_string(seed) + " --out " + out;
}

TEST(EmulateTool, SameSeedGivesABitIdenticalBagAndAnotherSeedDoesNot) {
  const std::string directory = scratch_directory();
  const auto first = run_tool("emulate", emulate_arguments(directory + "/a.bag", 3));
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const auto second = run_tool("emulate", emulate_arguments(directory + "/b.bag", 3));
  ASSERT_EQ(second.exit_code, 0) << second.output;
  const auto other = run_tool("emulate", emulate_arguments(directory + "/c.bag", 4));
  ASSERT_EQ(other.exit_code, 0) << other.output;
  const std::string a = read_file(directory + "/a.bag");
  EXPECT_GT(a.size(), 100000u);
  EXPECT_TRUE(a == read_file(directory + "/b.bag")) << "same seed and config must give the same bytes";
  EXPECT_FALSE(a == read_file(directory + "/c.bag"));

  std::size_t count = 0;
  std::int64_t first_stamp_ns = 0;
  imu_lab::ros_io::for_each_imu(directory + "/a.bag", "/imu/raw", [&](const imu_lab::io::ImuRecord& record) {
    if (count++ == 0) first_stamp_ns = record.stamp_ns;
  });
  EXPECT_EQ(count, 4000u);
  EXPECT_EQ(first_stamp_ns, 1000000000005000000);  // start time from the config, stamp at interval end
  const auto topics = imu_lab::ros_io::list_topics(directory + "/a.bag");
  std::vector<std::string> names;
  for (const auto& topic : topics) names.push_back(topic.name + " " + topic.datatype);
  EXPECT_EQ(names,
            (std::vector<std::string>{"/imu/increment imu_lab/ImuIncrement", "/imu/raw sensor_msgs/Imu",
                                      "/imu/temperature sensor_msgs/Temperature", "/imu/truth imu_lab/ImuTruth"}));
}

TEST(EmulateTool, BadProfileIsRefusedNamingTheKeyAndWritesNothing) {
  const std::string directory = scratch_directory();
  std::string profile = read_file(kProfile);
  // A negative density (a negative variance): the gyro's white-rate density.
  const auto key = profile.find("density_rad_s_per_sqrt_hz:");
  ASSERT_NE(key, std::string::npos);
  const auto colon = profile.find(':', key);
  profile.insert(colon + 2, "-");  // ": 4.4e-5" -> ": -4.4e-5"
  const std::string bad_profile = directory + "/bad.yaml";
  std::ofstream(bad_profile) << profile;
  const std::string out = directory + "/never.bag";
  const auto result =
      run_tool("emulate", "--profile " + bad_profile + " --scenario " + kScenario + " --duration-s 5 --out " + out);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("gyro.noise.white_rate.density_rad_s_per_sqrt_hz"), std::string::npos) << result.output;
  EXPECT_FALSE(file_exists(out));
  // Nothing half-written either.
  EXPECT_EQ(list_directory(directory), std::vector<std::string>{"bad.yaml"});
}

TEST(EmulateTool, UnknownProfileNameSaysWhereItLooked) {
  const auto result = run_tool("emulate", "--profile no_such_sensor --out /tmp/never.bag --duration-s 1");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("no_such_sensor"), std::string::npos) << result.output;
}

}  // namespace
