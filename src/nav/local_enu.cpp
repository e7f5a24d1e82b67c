#include "imu_lab/nav/local_enu.h"

#include <cmath>

namespace imu_lab {
namespace nav {

LocalEnuFrame::LocalEnuFrame(const nav::EarthModelConfig& earth, double origin_latitude_rad,
                             double origin_longitude_rad, double origin_height_m) {
  if (earth.shape == EarthShape::kWgs84Rotating) {
    semi_major_axis_m_ = wgs84::kSemiMajorAxis_m;
    eccentricity_squared_ = wgs84::kEccentricitySquared;
  } else {
    semi_major_axis_m_ = earth.sphere_radius_m;
    eccentricity_squared_ = 0.0;
  }
  origin_earth_centred_m_ = earth_centred_m(origin_latitude_rad, origin_longitude_rad, origin_height_m);
  const double sin_lat = std::sin(origin_latitude_rad);
  const double cos_lat = std::cos(origin_latitude_rad);
  const double sin_lon = std::sin(origin_longitude_rad);
  const double cos_lon = std::cos(origin_longitude_rad);
  earth_centred_to_enu_ << -sin_lon, cos_lon, 0.0,      // east
      -sin_lat * cos_lon, -sin_lat * sin_lon, cos_lat,  // north
      cos_lat * cos_lon, cos_lat * sin_lon, sin_lat;    // up
}

Eigen::Vector3d LocalEnuFrame::earth_centred_m(double latitude_rad, double longitude_rad, double height_m) const {
  const double sin_lat = std::sin(latitude_rad);
  const double prime_vertical_radius_m =
      semi_major_axis_m_ / std::sqrt(1.0 - eccentricity_squared_ * sin_lat * sin_lat);
  const double horizontal_m = (prime_vertical_radius_m + height_m) * std::cos(latitude_rad);
  return {horizontal_m * std::cos(longitude_rad), horizontal_m * std::sin(longitude_rad),
          (prime_vertical_radius_m * (1.0 - eccentricity_squared_) + height_m) * sin_lat};
}

Eigen::Vector3d LocalEnuFrame::enu_m(double latitude_rad, double longitude_rad, double height_m) const {
  return earth_centred_to_enu_ * (earth_centred_m(latitude_rad, longitude_rad, height_m) - origin_earth_centred_m_);
}

}  // namespace nav
}  // namespace imu_lab
