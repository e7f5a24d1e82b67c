// One IMU sample as the fitting code sees it: rates are averages over the interval ending at the
// stamp, in SI. Thermal and calibration fits both read bags into this.
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

struct ImuSample {
  double stamp_s = 0.0;
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();
};

}  // namespace imu_lab
