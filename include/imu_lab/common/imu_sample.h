// One IMU sample as the fitting code sees it: rates are averages over the interval ending at the
// stamp, in SI. Thermal and calibration fits both read bags into this.
#pragma once

#include <Eigen/Core>

namespace imu_lab {

struct ImuSample {
  double stamp_s = 0.0;
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();
};

}  // namespace imu_lab
