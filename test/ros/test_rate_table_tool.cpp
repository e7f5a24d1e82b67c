// The rate_table tool, run as a user runs it, on a bag from the emulate tool (tactical_mems on the
// rate_table_scale_factor scenario): both files written, the scale-factor error of gyro z matches
// the profile's; bad options exit 2 naming the option, a table file whose rates do not match the
// recording exits 1 listing the plateaus found, and neither writes anything.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <fstream>

#include "imu_lab/emulator/sensor_profile.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::file_exists;
using imu_lab::test_support::list_directory;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;

struct TableBag {
  std::string directory, bag;
};

const TableBag& table_bag() {
  static const TableBag bag = [] {
    TableBag b;
    b.directory = scratch_directory();
    b.bag = b.directory + "/table.bag";
    const auto result = run_tool("emulate",
                                 "--profile tactical_mems --scenario rate_table_scale_factor "
                                 "--rate-hz 100 --seed 3 --no-truth --no-increments --out " +
                                     b.bag);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return b;
  }();
  return bag;
}

TEST(RateTableTool, WritesBothFilesAndFindsTheProfilesScaleFactor) {
  const TableBag& b = table_bag();
  const std::string out = b.directory + "/report";
  const auto result = run_tool("rate_table", b.bag + " --scenario rate_table_scale_factor --out " + out);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("gyro z on the table axis, 18 plateaus"), std::string::npos) << result.output;
  ASSERT_TRUE(file_exists(out + "/rate_table_plateaus.csv"));
  const YAML::Node report = YAML::LoadFile(out + "/rate_table.yaml");
  EXPECT_EQ(report["gyro_axis"].as<std::string>(), "z");
  // tactical_mems: 150 ppm on z plus its thermal scale-factor term at the scenario's 20 degC; no
  // nonlinear terms, so the straight lines hold it. Within 4 sigma (one run).
  const auto profile =
      imu_lab::emulator::load_sensor_profile(imu_lab::ros_io::resolve_config("sensors", "tactical_mems"));
  const double expected_ppm =
      profile.gyro.scale_factor_error_ppm.z() + profile.gyro.thermal.scale_factor_ppm(20.0, 0.0).z();
  const YAML::Node estimate = report["straight_lines"]["scale_factor_error_ppm"];
  EXPECT_NEAR(estimate["value"].as<double>(), expected_ppm, 4.0 * estimate["sigma"].as<double>()) << result.output;
  EXPECT_FALSE(report["dead_zone"]["found"].as<bool>());
}

TEST(RateTableTool, BadOptionsExitTwoNamingTheOption) {
  const TableBag& b = table_bag();
  const std::string out = scratch_directory();
  const auto neither = run_tool("rate_table", b.bag + " --out " + out + "/r");
  EXPECT_EQ(neither.exit_code, 2) << neither.output;
  EXPECT_NE(neither.output.find("--scenario/--table"), std::string::npos) << neither.output;
  const auto window =
      run_tool("rate_table", b.bag + " --scenario rate_table_scale_factor --window-s 0 --out " + out + "/r");
  EXPECT_EQ(window.exit_code, 2) << window.output;
  EXPECT_NE(window.output.find("--window-s"), std::string::npos) << window.output;
  const auto not_a_table = run_tool("rate_table", b.bag + " --scenario static --out " + out + "/r");
  EXPECT_EQ(not_a_table.exit_code, 2) << not_a_table.output;
  EXPECT_NE(not_a_table.output.find("rate_table scenario"), std::string::npos) << not_a_table.output;
  const std::string table = out + "/typo.yaml";
  std::ofstream(table) << "latitude_deg: 50.45\nyaw_deg: 90\nrate_deg_s: [1, -1, 2]\n";
  const auto typo = run_tool("rate_table", b.bag + " --table " + table + " --out " + out + "/r");
  EXPECT_EQ(typo.exit_code, 2) << typo.output;
  EXPECT_NE(typo.output.find("rate_deg_s"), std::string::npos) << typo.output;
  EXPECT_EQ(list_directory(out), std::vector<std::string>{"typo.yaml"});
}

TEST(RateTableTool, RatesThatDoNotMatchTheRecordingExitOneListingThePlateaus) {
  const TableBag& b = table_bag();
  const std::string out = scratch_directory();
  const std::string table = out + "/table.yaml";
  std::ofstream(table) << "latitude_deg: 50.45\nyaw_deg: 90\nrates_deg_s: [0, 1, -1, 2, -2, 5, -5, 0]\n";
  const auto result = run_tool("rate_table", b.bag + " --table " + table + " --out " + out + "/r");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("18 plateau levels found"), std::string::npos) << result.output;
  EXPECT_FALSE(file_exists(out + "/r"));
}

}  // namespace
