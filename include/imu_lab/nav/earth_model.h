// Earth shape, gravity and rotation for the strapdown mechanisation, in the local-level ENU frame
// (REP-103: x east, y north, z up) at geodetic latitude / height.
//
// Two models:
//  - kWgs84Rotating: WGS-84 ellipsoid, Earth rate 7.292115e-5 rad/s, normal gravity from
//    Somigliana's closed formula with the second-order free-air height correction of NIMA TR8350.2
//    (eq. 4-3): g(L, h) = g0(L) [1 - 2/a (1 + f + m - 2 f sin^2 L) h + 3 h^2 / a^2].
//    Normal gravity already contains the centrifugal term and points along the ellipsoid normal.
//  - kSphereNonRotating: the textbook's Earth (Fomichev 2022 §1.1): a sphere of radius 6371 km fixed in
//    inertial space, gravity 9.81 m/s^2 at the surface, falling as (R / (R + h))^2
//    (kInverseSquare, the default; gives the vertical channel's sqrt(2) w0 divergence) or held
//    constant (kConstant; the vertical channel then has no gravity feedback at all).
//    With it the closed forms of Fomichev 2022 hold exactly (to first order in the errors).
#pragma once

#include <Eigen/Core>

#include "imu_lab/common/earth_constants.h"

namespace imu_lab {
namespace nav {

enum class SphereGravityLaw { kInverseSquare, kConstant };

struct EarthModelConfig {
  EarthShape shape = EarthShape::kWgs84Rotating;
  // Used only by kSphereNonRotating:
  SphereGravityLaw sphere_gravity_law = SphereGravityLaw::kInverseSquare;
  double sphere_radius_m = textbook_sphere::kRadius_m;
  double sphere_surface_gravity_m_s2 = textbook_sphere::kSurfaceGravity_m_s2;
};

class EarthModel {
 public:
  explicit EarthModel(const EarthModelConfig& config = EarthModelConfig());

  const EarthModelConfig& config() const { return config_; }

  // Magnitude of (normal) gravity; the vector is (0, 0, -g) in ENU.
  double gravity_m_s2(double latitude_rad, double height_m) const;
  // Radius of curvature in the meridian (north-south), R_M, and in the prime vertical, R_N.
  double meridian_radius_m(double latitude_rad) const;
  double prime_vertical_radius_m(double latitude_rad) const;
  double earth_rate_rad_s() const;  // zero for the non-rotating sphere
  // Earth rate relative to inertial space, in ENU: (0, W cos L, W sin L).
  Eigen::Vector3d earth_rate_enu_rad_s(double latitude_rad) const;
  // Rate of the ENU frame relative to the Earth caused by moving over the curved surface:
  // (-v_N / (R_M + h), v_E / (R_N + h), v_E tan L / (R_N + h)).
  Eigen::Vector3d transport_rate_enu_rad_s(const Eigen::Vector3d& velocity_enu_m_s, double latitude_rad,
                                           double height_m) const;
  // Schuler frequency sqrt(g / R) at the surface (the equator for WGS-84).
  double schuler_rate_rad_s() const;

 private:
  EarthModelConfig config_;
};

}  // namespace nav
}  // namespace imu_lab
