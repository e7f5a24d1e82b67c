// The estimated parameters as one vector, in the order the covariance and the files use:
// accelerometer bias (3), accelerometer K (9, row-major), gyro bias (3), gyro K (9, row-major),
// gyro g-sensitivity G (9, row-major). Names like "gyro.K.xy" (row x, column y).
#pragma once

#include <Eigen/Core>
#include <string>

#include "imu_lab/calib/imu_calibration.h"

namespace imu_lab {
namespace calib {

constexpr int kParameterCount = 33;
using ParameterVector = Eigen::Matrix<double, kParameterCount, 1>;
using ParameterCovariance = Eigen::Matrix<double, kParameterCount, kParameterCount>;

namespace parameter_offset {
constexpr int kAccelerometerBias = 0;
constexpr int kAccelerometerK = 3;
constexpr int kGyroBias = 12;
constexpr int kGyroK = 15;
constexpr int kGyroGSensitivity = 24;
}  // namespace parameter_offset

std::string parameter_name(int index);
ParameterVector to_parameter_vector(const ImuCalibration& calibration);
ImuCalibration from_parameter_vector(const ParameterVector& values);

}  // namespace calib
}  // namespace imu_lab
