#include "imu_lab/emulator/local_level_kinematics.h"

#include <cmath>

#include "imu_lab/emulator/earth_model.h"

namespace imu_lab {
namespace emulator {

RadiiOfCurvature radii_of_curvature(EarthShape model, double latitude_rad) {
  if (model == EarthShape::kSphereNonRotating) return {textbook_sphere::kRadius_m, textbook_sphere::kRadius_m};
  const double s = std::sin(latitude_rad);
  const double w2 = 1.0 - wgs84::kEccentricitySquared * s * s;
  const double prime_vertical = wgs84::kSemiMajorAxis_m / std::sqrt(w2);
  return {prime_vertical * (1.0 - wgs84::kEccentricitySquared) / w2, prime_vertical};
}

Eigen::Vector3d transport_rate_enu_rad_s(EarthShape model, double latitude_rad, double height_m,
                                         const Eigen::Vector3d& velocity_enu_m_s) {
  const RadiiOfCurvature radii = radii_of_curvature(model, latitude_rad);
  const double east_over_radius = velocity_enu_m_s.x() / (radii.prime_vertical_m + height_m);
  return {-velocity_enu_m_s.y() / (radii.meridian_m + height_m), east_over_radius,
          east_over_radius * std::tan(latitude_rad)};
}

TruthState truth_from_local_level(const LocalLevelMotion& motion, EarthShape model, double time_s,
                                  double temperature_c) {
  const Eigen::Vector3d earth_rate = earth_rate_enu_rad_s(model, motion.latitude_rad);
  const Eigen::Vector3d transport_rate =
      transport_rate_enu_rad_s(model, motion.latitude_rad, motion.height_m, motion.velocity_enu_m_s);
  const Eigen::Vector3d gravity_enu(0.0, 0.0, -normal_gravity_m_s2(model, motion.latitude_rad, motion.height_m));
  const Eigen::Matrix3d enu_to_body = motion.attitude_body_to_enu.toRotationMatrix().transpose();

  TruthState truth;
  truth.time_s = time_s;
  truth.attitude_body_to_enu = motion.attitude_body_to_enu;
  truth.angular_rate_body_rad_s = motion.rate_body_wrt_enu_rad_s + enu_to_body * (earth_rate + transport_rate);
  truth.specific_force_body_m_s2 =
      enu_to_body *
      (motion.acceleration_enu_m_s2 + (2.0 * earth_rate + transport_rate).cross(motion.velocity_enu_m_s) - gravity_enu);
  truth.latitude_rad = motion.latitude_rad;
  truth.longitude_rad = motion.longitude_rad;
  truth.height_m = motion.height_m;
  truth.velocity_enu_m_s = motion.velocity_enu_m_s;
  truth.temperature_c = temperature_c;
  return truth;
}

}  // namespace emulator
}  // namespace imu_lab
