// Gravity and Earth rotation at a point, in local ENU.
#pragma once

#include <Eigen/Core>

#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

constexpr double kWgs84SemiMajorAxis_m = 6378137.0;
constexpr double kWgs84Flattening = 1.0 / 298.257223563;
constexpr double kWgs84EarthRate_rad_s = 7.292115e-5;
constexpr double kSphereRadius_m = 6371000.0;
constexpr double kSphereGravity_m_s2 = 9.81;

// WGS-84 normal gravity magnitude: Somigliana's formula with the second-order height
// correction (NIMA TR8350.2 eq. 4-1 and 4-3). Sphere model: 9.81 (R / (R + h))^2.
double normal_gravity_m_s2(EarthModel model, double latitude_rad, double height_m);

// Earth rate in ENU: (0, w cos(lat), w sin(lat)); zero for the non-rotating sphere.
Eigen::Vector3d earth_rate_enu_rad_s(EarthModel model, double latitude_rad);

}  // namespace emulator
}  // namespace imu_lab
