// The install space as `catkin_make install` makes it (here `cmake --install` of this build into a
// scratch prefix): its tools run without a sourced workspace and find the package's configuration
// and plot scripts there, and its launch files load from it with their node parameter templates.
#include <gtest/gtest.h>

#include <string>

#include "ros_test_support.h"

namespace {

using imu_lab::test_support::file_exists;
using imu_lab::test_support::run_command;
using imu_lab::test_support::scratch_directory;

using imu_lab::test_support::contains;

TEST(InstallSpace, ToolsAndLaunchFilesWorkFromTheInstallSpace) {
  const std::string directory = scratch_directory();
  const std::string prefix = directory + "/install";
  const auto installed = run_command(std::string("cmake --install ") + IMU_LAB_BUILD_DIR + " --prefix " + prefix);
  ASSERT_EQ(installed.exit_code, 0) << installed.output;
  for (const char* file : {"lib/imu_lab/emulate", "lib/imu_lab/strapdown_navigator", "lib/libimu_lab_nodelets.so",
                           "share/imu_lab/nodelet_plugins.xml", "share/imu_lab/config/nodes/allan_monitor.yaml",
                           "share/imu_lab/scripts/plot_allan.py", "share/imu_lab/launch/full_chain.launch"}) {
    EXPECT_TRUE(file_exists(prefix + "/" + file)) << file << " not installed";
  }

  // A user's shell with only the install space: no devel space, no sourced setup.
  const std::string shell =
      "env -i PATH=/usr/bin:/bin HOME=" + directory + " ROS_PACKAGE_PATH=" + prefix + "/share:/usr/share ";
  const auto emulate =
      run_command(shell + prefix + "/lib/imu_lab/emulate --scenario coning --duration-s 2 --rate-hz 100 --out " +
                  directory + "/c.bag");
  ASSERT_EQ(emulate.exit_code, 0) << emulate.output;
  const auto allan = run_command(shell + prefix + "/lib/imu_lab/allan " + directory + "/c.bag --no-identify --out " +
                                 directory + "/report");
  EXPECT_EQ(allan.exit_code, 0) << allan.output;
  EXPECT_TRUE(file_exists(directory + "/report/allan.png")) << "the installed plot script did not run:\n"
                                                            << allan.output;

  const auto found = run_command(shell + "rospack find imu_lab");
  EXPECT_EQ(found.output, prefix + "/share/imu_lab\n");
  const auto launch =
      run_command(shell + "roslaunch --dump-params " + prefix + "/share/imu_lab/launch/full_chain.launch rviz:=false");
  EXPECT_EQ(launch.exit_code, 0) << launch.output;
  EXPECT_TRUE(contains(launch.output, "/strapdown_navigator/vertical_channel: held")) << launch.output;  // its template
  EXPECT_TRUE(contains(launch.output, "/allan_monitor/statistics:")) << launch.output;
}

}  // namespace
