// scripts/rviz_allan_screenshot as a user runs it on their own bag (issue 46: it worked only with
// the emulator): bag:= replays the bag into allan_monitor and the panel is captured once it has
// drawn the identified model; a missing bag or an emulator argument beside a bag is refused with
// exit 2 before anything starts.
#include <gtest/gtest.h>

#include <filesystem>

#include "allan_test_support.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::contains;
using imu_lab::test_support::file_exists;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_command;
using imu_lab::test_support::scratch_directory;
using imu_lab::test_support::white_noise_samples;
using imu_lab::test_support::write_imu_bag;

// Through the real checkout (the workspace links config/): the script finds the workspace from its
// own folder.
const std::string kScript =
    (std::filesystem::canonical(IMU_LAB_CONFIG_DIR).parent_path() / "scripts" / "rviz_allan_screenshot").string();

TEST(RvizAllanScreenshot, CapturesThePanelOnAUsersBag) {
  const std::string directory = scratch_directory();
  const std::string bag = directory + "/my_imu.bag";
  write_imu_bag(bag, white_noise_samples(60000, 5'000'000, 5), "/imu/data_raw");  // 300 s at 200 Hz
  const std::string png = directory + "/panel.png";
  // The model after 30 s of record (sim time: the bag's stamps).
  const auto run = run_command("IMU_LAB_SCREENSHOT_IDENTIFY_S=30 " + kScript + " " + png + " bag:=" + bag +
                               " imu_topic:=/imu/data_raw");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(contains(run.output, "rviz_allan_screenshot: wrote " + png)) << run.output;
  ASSERT_TRUE(file_exists(png));
  EXPECT_EQ(read_file(png).substr(1, 3), "PNG");
}

TEST(RvizAllanScreenshot, RefusesAMissingBagOrEmulatorArgumentsBesideABag) {
  const std::string directory = scratch_directory();
  const auto missing = run_command(kScript + " " + directory + "/x.png bag:=" + directory + "/no_such.bag");
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_TRUE(contains(missing.output, "no bag " + directory + "/no_such.bag")) << missing.output;
  const std::string bag = directory + "/my_imu.bag";
  write_imu_bag(bag, white_noise_samples(100, 5'000'000, 5));
  const auto mixed = run_command(kScript + " " + directory + "/x.png bag:=" + bag + " profile:=tactical_mems");
  EXPECT_EQ(mixed.exit_code, 2) << mixed.output;
  EXPECT_TRUE(contains(mixed.output, "not profile:=tactical_mems")) << mixed.output;
  EXPECT_FALSE(file_exists(directory + "/x.png"));
}

}  // namespace
