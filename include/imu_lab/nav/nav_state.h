// The navigation solution after each step, as the ROS layer publishes it.
//
// Frames (REP-103 / REP-145): body = IMU sensor frame (x forward, y left, z up); navigation frame
// = local-level ENU at the current position (x east, y north, z up). q_body_to_enu rotates body
// coordinates into ENU (v_enu = q_body_to_enu * v_body); identity means body x east, y north,
// z up, and a yaw about z is measured from east towards north. Position is geodetic on the
// configured Earth model (WGS-84 or the textbook sphere).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace imu_lab {
namespace nav {

struct NavState {
  double stamp_s = 0.0;
  Eigen::Quaterniond q_body_to_enu = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity_enu_m_s = Eigen::Vector3d::Zero();  // relative to the Earth
  double latitude_rad = 0.0;
  double longitude_rad = 0.0;  // wrapped to (-pi, pi]
  double height_m = 0.0;       // above the ellipsoid (or sphere)
};

}  // namespace nav
}  // namespace imu_lab
