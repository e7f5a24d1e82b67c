// Geodetic position -> local ENU metres relative to a fixed origin (the navigation's initial
// position): exact through Earth-centred coordinates on the navigator's Earth model (WGS-84
// ellipsoid or the sphere), so it stays right over any distance, not just near the origin.
// The published odometry and tf use it: ROS tools want a Cartesian world frame (REP-103 ENU).
#pragma once

#include <Eigen/Core>

#include "imu_lab/nav/earth_model.h"

namespace imu_lab {
namespace nav {

class LocalEnuFrame {
 public:
  LocalEnuFrame(const nav::EarthModelConfig& earth, double origin_latitude_rad, double origin_longitude_rad,
                double origin_height_m);

  // East, north, up of the point relative to the origin, in the origin's ENU axes [m].
  Eigen::Vector3d enu_m(double latitude_rad, double longitude_rad, double height_m) const;

 private:
  Eigen::Vector3d earth_centred_m(double latitude_rad, double longitude_rad, double height_m) const;

  double semi_major_axis_m_ = 0.0;
  double eccentricity_squared_ = 0.0;
  Eigen::Vector3d origin_earth_centred_m_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d earth_centred_to_enu_ = Eigen::Matrix3d::Identity();
};

}  // namespace nav
}  // namespace imu_lab
