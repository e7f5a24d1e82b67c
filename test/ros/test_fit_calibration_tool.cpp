// The fit_calibration tool, run as a user runs it, on bags from the emulate tool: both modes write
// the calibration YAML (which the corrector's loader reads back), the Kalibr/OpenVINS intrinsics
// and the report; the estimates match the emulated sensor; bad inputs exit non-zero with a message.
#include <gtest/gtest.h>

#include <fstream>

#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/sensor_channel.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::file_exists;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;
using imu_lab::test_support::write_quick_twelve_position_schedule;

struct QuickBag {
  std::string directory, schedule, bag;
};

const QuickBag& quick_bag() {
  static const QuickBag bag = [] {
    QuickBag b;
    b.directory = scratch_directory();
    b.schedule = write_quick_twelve_position_schedule(b.directory);
    b.bag = b.directory + "/calibration.bag";
    const auto result = run_tool(
        "emulate", "--profile tactical_mems --scenario " + b.schedule + " --rate-hz 100 --seed 2 --out " + b.bag);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return b;
  }();
  return bag;
}

TEST(FitCalibrationTool, KnownOrientationsWritesAllThreeFilesAndMatchesTheSensor) {
  const QuickBag& b = quick_bag();
  const std::string out = b.directory + "/known.yaml";
  const auto result = run_tool("fit_calibration", b.bag + " --schedule " + b.schedule + " --out " + out);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("held-out check"), std::string::npos);
  ASSERT_TRUE(file_exists(b.directory + "/known_kalibr_imu_chain.yaml"));
  ASSERT_TRUE(file_exists(b.directory + "/known_report.txt"));
  EXPECT_NE(read_file(b.directory + "/known_kalibr_imu_chain.yaml").find("R_IMUtoGYRO:"), std::string::npos);
  const auto calibration = imu_lab::calib::load_calibration(out);
  // The emulated sensor at the scenario's 20 degC (the profile's thermal terms refer to 25 degC).
  const auto profile =
      imu_lab::emulator::load_sensor_profile(imu_lab::ros_io::resolve_config("sensors", "tactical_mems"));
  Eigen::Matrix3d accelerometer_k = profile.accelerometer.scale_misalignment_matrix();
  accelerometer_k.diagonal() += profile.accelerometer.thermal.scale_factor_ppm(20.0, 0.0) * 1e-6;
  EXPECT_LT((calibration.accelerometer.scale_misalignment - accelerometer_k).cwiseAbs().maxCoeff(), 1e-4);
  Eigen::Matrix3d gyro_k = profile.gyro.scale_misalignment_matrix();
  gyro_k.diagonal() += profile.gyro.thermal.scale_factor_ppm(20.0, 0.0) * 1e-6;
  EXPECT_LT((calibration.gyro.scale_misalignment - gyro_k).cwiseAbs().maxCoeff(), 2e-4);
}

TEST(FitCalibrationTool, UnknownOrientationsWithHeldOutRests) {
  const QuickBag& b = quick_bag();
  const std::string out = b.directory + "/unknown.yaml";
  const auto result =
      run_tool("fit_calibration", b.bag + " --latitude-deg 50.45 --height-m 180 --held-out-last 3 --out " + out);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("mode: unknown orientations"), std::string::npos) << result.output;
  EXPECT_NE(read_file(out).find("held_out_rests: 3"), std::string::npos);
  EXPECT_NO_THROW(imu_lab::calib::load_calibration(out));
}

TEST(FitCalibrationTool, RefusesBadInputWithAMessage) {
  const QuickBag& b = quick_bag();
  const auto too_few = run_tool("fit_calibration", b.bag + " --latitude-deg 50 --height-m 0 --held-out-last 6 --out " +
                                                       b.directory + "/few.yaml");
  EXPECT_EQ(too_few.exit_code, 1) << too_few.output;
  EXPECT_NE(too_few.output.find("needs at least 9: record 3 more positions"), std::string::npos) << too_few.output;
  EXPECT_FALSE(file_exists(b.directory + "/few.yaml"));
  const auto not_a_schedule =
      run_tool("fit_calibration", b.bag + " --schedule static --out " + b.directory + "/static.yaml");
  EXPECT_EQ(not_a_schedule.exit_code, 2) << not_a_schedule.output;
  EXPECT_NE(not_a_schedule.output.find("multi_position"), std::string::npos) << not_a_schedule.output;
}

}  // namespace
