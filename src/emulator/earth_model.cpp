#include "imu_lab/emulator/earth_model.h"

#include <cmath>

namespace imu_lab {
namespace emulator {

double normal_gravity_m_s2(EarthShape model, double latitude_rad, double height_m) {
  if (model == EarthShape::kSphereNonRotating) {
    const double ratio = textbook_sphere::kRadius_m / (textbook_sphere::kRadius_m + height_m);
    return textbook_sphere::kSurfaceGravity_m_s2 * ratio * ratio;
  }
  const double s2 = std::sin(latitude_rad) * std::sin(latitude_rad);
  const double on_ellipsoid = wgs84::kEquatorialGravity_m_s2 * (1.0 + wgs84::kSomiglianaConstant * s2) /
                              std::sqrt(1.0 - wgs84::kEccentricitySquared * s2);
  const double a = wgs84::kSemiMajorAxis_m;
  const double f = wgs84::kFlattening;
  return on_ellipsoid * (1.0 - 2.0 / a * (1.0 + f + wgs84::kGravityRatio - 2.0 * f * s2) * height_m +
                         3.0 * height_m * height_m / (a * a));
}

Eigen::Vector3d earth_rate_enu_rad_s(EarthShape model, double latitude_rad) {
  if (model == EarthShape::kSphereNonRotating) return Eigen::Vector3d::Zero();
  return wgs84::kEarthRate_rad_s * Eigen::Vector3d(0.0, std::cos(latitude_rad), std::sin(latitude_rad));
}

}  // namespace emulator
}  // namespace imu_lab
