#include "imu_lab/calib/calibration_parameters.h"

namespace imu_lab {
namespace calib {
namespace {

constexpr const char* kAxes = "xyz";

void put(ParameterVector& values, int offset, const Eigen::Matrix3d& matrix) {
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) values[offset + 3 * row + column] = matrix(row, column);
  }
}

Eigen::Matrix3d take(const ParameterVector& values, int offset) {
  Eigen::Matrix3d matrix;
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) matrix(row, column) = values[offset + 3 * row + column];
  }
  return matrix;
}

}  // namespace

std::string parameter_name(int index) {
  using namespace parameter_offset;
  const std::string triad = index < kGyroBias ? "accelerometer" : "gyro";
  if (index < kAccelerometerK || (index >= kGyroBias && index < kGyroK)) {
    return triad + ".bias." + kAxes[index % 3];
  }
  const int offset = index < kGyroBias ? kAccelerometerK : (index < kGyroGSensitivity ? kGyroK : kGyroGSensitivity);
  const int element = index - offset;
  const std::string matrix = offset == kGyroGSensitivity ? ".G." : ".K.";
  return triad + matrix + kAxes[element / 3] + kAxes[element % 3];
}

ParameterVector to_parameter_vector(const ImuCalibration& calibration) {
  using namespace parameter_offset;
  ParameterVector values;
  values.segment<3>(kAccelerometerBias) = calibration.accelerometer.bias;
  put(values, kAccelerometerK, calibration.accelerometer.scale_misalignment);
  values.segment<3>(kGyroBias) = calibration.gyro.bias;
  put(values, kGyroK, calibration.gyro.scale_misalignment);
  put(values, kGyroGSensitivity, calibration.gyro.g_sensitivity);
  return values;
}

ImuCalibration from_parameter_vector(const ParameterVector& values) {
  using namespace parameter_offset;
  ImuCalibration calibration;
  calibration.accelerometer.bias = values.segment<3>(kAccelerometerBias);
  calibration.accelerometer.scale_misalignment = take(values, kAccelerometerK);
  calibration.gyro.bias = values.segment<3>(kGyroBias);
  calibration.gyro.scale_misalignment = take(values, kGyroK);
  calibration.gyro.g_sensitivity = take(values, kGyroGSensitivity);
  return calibration;
}

}  // namespace calib
}  // namespace imu_lab
