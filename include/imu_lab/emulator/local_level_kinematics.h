// The truth a strapdown IMU senses, from the motion of a point over the Earth and the body's
// attitude in the local ENU frame there (the navigation equations run backwards):
//   inertial body rate  w_ib^b = w_nb^b + C^T (w_ie^n + w_en^n)
//   specific force      f^b    = C^T (dv^n/dt + (2 w_ie^n + w_en^n) x v^n - g^n),  g^n = (0, 0, -g)
// with C = attitude body -> ENU, v^n the ENU velocity and dv^n/dt the derivative of its ENU
// components. Shared by every moving scenario so they agree on the Earth model.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "imu_lab/emulator/motion_source.h"
#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

struct RadiiOfCurvature {
  double meridian_m = 0.0;        // M (north-south)
  double prime_vertical_m = 0.0;  // N (east-west)
};

// WGS-84: M = a (1 - e^2) / (1 - e^2 sin^2 lat)^1.5, N = a / sqrt(1 - e^2 sin^2 lat); sphere: R.
RadiiOfCurvature radii_of_curvature(EarthShape model, double latitude_rad);

// Rate of the ENU frame w.r.t. the Earth while moving: (-v_N / (M + h), v_E / (N + h),
// v_E tan(lat) / (N + h)).
Eigen::Vector3d transport_rate_enu_rad_s(EarthShape model, double latitude_rad, double height_m,
                                         const Eigen::Vector3d& velocity_enu_m_s);

struct LocalLevelMotion {
  double latitude_rad = 0.0;
  double longitude_rad = 0.0;
  double height_m = 0.0;
  Eigen::Vector3d velocity_enu_m_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration_enu_m_s2 = Eigen::Vector3d::Zero();  // d/dt of v^n's components
  Eigen::Quaterniond attitude_body_to_enu = Eigen::Quaterniond::Identity();
  Eigen::Vector3d rate_body_wrt_enu_rad_s = Eigen::Vector3d::Zero();  // w_nb^b, body axes
};

TruthState truth_from_local_level(const LocalLevelMotion& motion, EarthShape model, double time_s,
                                  double temperature_c);

}  // namespace emulator
}  // namespace imu_lab
