// Which static orientation each window of a thermal test was in: static windows are grouped by
// the direction of gravity in the body (no schedule file needed, so a real test works the same
// as an emulated one). The known input of each orientation is gravity projected into the body
// (accelerometers) and the Earth rate projected into the body (gyros).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "imu_lab/common/earth_constants.h"
#include "imu_lab/thermal/thermal_windows.h"

namespace imu_lab {
namespace thermal {

struct EarthReference {
  double gravity_m_s2 = 9.80665;
  double earth_rate_rad_s = wgs84::kEarthRate_rad_s;
  double latitude_rad = 0.0;
};

struct OrientationCluster {
  Eigen::Vector3d up_body = Eigen::Vector3d::UnitZ();                   // unit
  Eigen::Vector3d specific_force_input_m_s2 = Eigen::Vector3d::Zero();  // g * up
  // Vertical part from `up` exactly; the horizontal part's direction is taken from the mean
  // gyro output (gyrocompassing), so it is only as good as the gyro bias is small against the
  // Earth rate. It enters only the gyro scale-factor terms.
  Eigen::Vector3d angular_rate_input_rad_s = Eigen::Vector3d::Zero();
  int window_count = 0;
};

struct OrientationAssignment {
  std::vector<OrientationCluster> clusters;
  std::vector<int> cluster_of_window;  // per window; -1 for windows that are not static
};

// Windows within max_angle_rad of a cluster's mean direction join it (greedy, in time order).
OrientationAssignment cluster_by_gravity(const std::vector<ThermalWindow>& windows, double max_angle_rad,
                                         const EarthReference& earth);

}  // namespace thermal
}  // namespace imu_lab
