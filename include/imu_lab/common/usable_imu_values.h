// Which IMU values a consumer may use: finite and of a size a sensor can measure. The samples
// themselves are io::ImuRecord (io/imu_records.h).
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace imu_lab {

// Beyond this magnitude an IMU value is unusable like NaN/Inf: no sensor measures 1e100 of
// anything, and the sums of squares that averages and Allan statistics accumulate overflow to Inf
// on such values (1e308 rad/s made the Allan engine's noise-type estimate throw). The Allan
// engine leaves such values out of their channel; tools that use every sample refuse them.
constexpr double kLargestUsableImuValue = 1e100;
inline bool is_usable_imu_value(double value) { return std::abs(value) <= kLargestUsableImuValue; }  // false for NaN
inline bool is_usable_imu_vector(const Eigen::Vector3d& values) {
  return is_usable_imu_value(values.x()) && is_usable_imu_value(values.y()) && is_usable_imu_value(values.z());
}

}  // namespace imu_lab
