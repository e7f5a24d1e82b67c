// Gravity and Earth rotation at a point, in local ENU.
#pragma once

#include <Eigen/Core>

#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

// Computed here from the shared constants (common/earth_constants.h), independently of the
// navigator's nav/earth_model.h: the emulator is the navigator's oracle.

// WGS-84 normal gravity magnitude: Somigliana's formula with the second-order height
// correction (NIMA TR8350.2 eq. 4-1 and 4-3). Sphere model: 9.81 (R / (R + h))^2.
double normal_gravity_m_s2(EarthShape model, double latitude_rad, double height_m);

// Earth rate in ENU: (0, w cos(lat), w sin(lat)); zero for the non-rotating sphere.
Eigen::Vector3d earth_rate_enu_rad_s(EarthShape model, double latitude_rad);

}  // namespace emulator
}  // namespace imu_lab
