// The calibration YAML reads back what was written; bad files are refused naming the key; the
// Kalibr/OpenVINS intrinsics rebuild our K and G (Ta Q = K_a, Tw R_IMUtoGYRO Q = K_g, Tg Q = G,
// Tw and Ta lower triangular with positive diagonals, the rotations proper).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "calib_test_support.h"
#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/calib/calibration_report.h"
#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace {

calib::CalibrationResult result_with(const calib::ImuCalibration& calibration) {
  calib::CalibrationResult result;
  result.calibration = calibration;
  result.values = calib::to_parameter_vector(calibration);
  return result;
}

calib::ImuCalibration example_calibration() {
  calib::ImuCalibration calibration;
  const auto profile = calib_test::tactical_test_profile(/*with_g_sensitivity=*/true);
  calibration.gyro.scale_misalignment = profile.gyro.scale_misalignment_matrix();
  calibration.gyro.bias = profile.gyro.bias_fixed;
  calibration.gyro.g_sensitivity = profile.gyro.g_sensitivity;
  calibration.accelerometer.scale_misalignment = profile.accelerometer.scale_misalignment_matrix();
  calibration.accelerometer.bias = profile.accelerometer.bias_fixed;
  return calibration;
}

std::string scratch_file(const std::string& name) { return testing::TempDir() + "/calib_files_" + name; }

TEST(CalibFiles, YamlRoundTrip) {
  const calib::ImuCalibration written = example_calibration();
  const std::string path = scratch_file("round_trip.yaml");
  write_file_atomically(path, calib::calibration_yaml(result_with(written)));
  const calib::ImuCalibration read = calib::load_calibration(path);
  EXPECT_TRUE(read.gyro.scale_misalignment.isApprox(written.gyro.scale_misalignment, 1e-11));
  EXPECT_TRUE(read.gyro.bias.isApprox(written.gyro.bias, 1e-11));
  EXPECT_TRUE(read.gyro.g_sensitivity.isApprox(written.gyro.g_sensitivity, 1e-11));
  EXPECT_TRUE(read.accelerometer.scale_misalignment.isApprox(written.accelerometer.scale_misalignment, 1e-11));
  EXPECT_TRUE(read.accelerometer.bias.isApprox(written.accelerometer.bias, 1e-11));
  EXPECT_FALSE(calib::calibration_report(result_with(written)).empty());
}

TEST(CalibFiles, SingularMatrixAndWrongFormatAreRefusedByKey) {
  calib::ImuCalibration singular = example_calibration();
  singular.accelerometer.scale_misalignment.row(2).setZero();
  const std::string path = scratch_file("singular.yaml");
  write_file_atomically(path, calib::calibration_yaml(result_with(singular)));
  try {
    calib::load_calibration(path);
    FAIL() << "a singular K was accepted";
  } catch (const ConfigError& error) {
    EXPECT_EQ(error.key(), "accelerometer.scale_misalignment");
  }
  const std::string other = scratch_file("other.yaml");
  write_file_atomically(other, "name: tactical_mems\n");
  try {
    calib::load_calibration(other);
    FAIL() << "a file without the format key was accepted";
  } catch (const ConfigError& error) {
    EXPECT_EQ(error.key(), "format");
  }
}

TEST(CalibFiles, KalibrIntrinsicsRebuildOurModel) {
  const calib::ImuCalibration ours = example_calibration();
  const calib::KalibrIntrinsics k = calib::kalibr_intrinsics(ours);
  const Eigen::Matrix3d& q = k.body_to_imu;
  EXPECT_TRUE((k.Ta * k.R_IMUtoACC * q).isApprox(ours.accelerometer.scale_misalignment, 1e-12));
  EXPECT_TRUE((k.Tw * k.R_IMUtoGYRO * q).isApprox(ours.gyro.scale_misalignment, 1e-12));
  EXPECT_TRUE((k.Tg * q).isApprox(ours.gyro.g_sensitivity, 1e-12));
  EXPECT_TRUE(k.R_IMUtoACC.isIdentity());
  for (const Eigen::Matrix3d* lower : {&k.Tw, &k.Ta}) {
    EXPECT_EQ((*lower)(0, 1), 0.0);
    EXPECT_EQ((*lower)(0, 2), 0.0);
    EXPECT_EQ((*lower)(1, 2), 0.0);
    EXPECT_GT(lower->diagonal().minCoeff(), 0.0);
  }
  for (const Eigen::Matrix3d* rotation : {&k.R_IMUtoGYRO, &q}) {
    EXPECT_TRUE((*rotation * rotation->transpose()).isIdentity(1e-12));
    EXPECT_NEAR(rotation->determinant(), 1.0, 1e-12);
  }
  const std::string text = calib::kalibr_imu_chain_yaml(result_with(ours), "/imu/raw", 200.0);
  for (const char* key : {"Tw:", "R_IMUtoGYRO:", "Ta:", "R_IMUtoACC:", "Tg:", "model: \"kalibr\""}) {
    EXPECT_NE(text.find(key), std::string::npos) << key;
  }
}

}  // namespace
}  // namespace imu_lab
