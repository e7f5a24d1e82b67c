#include "imu_lab/emulator/earth_model.h"

#include <cmath>

namespace imu_lab {
namespace emulator {

namespace {
constexpr double kEquatorGravity_m_s2 = 9.7803253359;
constexpr double kSomiglianaK = 0.00193185265241;         // (b g_p) / (a g_e) - 1
constexpr double kFirstEccentricitySquared = 0.00669437999013;
constexpr double kGravityRatioM = 0.00344978650684;       // w^2 a^2 b / GM
}  // namespace

double normal_gravity_m_s2(EarthModel model, double latitude_rad, double height_m) {
  if (model == EarthModel::kSphereNonRotating) {
    const double ratio = kSphereRadius_m / (kSphereRadius_m + height_m);
    return kSphereGravity_m_s2 * ratio * ratio;
  }
  const double s2 = std::sin(latitude_rad) * std::sin(latitude_rad);
  const double on_ellipsoid = kEquatorGravity_m_s2 * (1.0 + kSomiglianaK * s2) /
                              std::sqrt(1.0 - kFirstEccentricitySquared * s2);
  const double a = kWgs84SemiMajorAxis_m;
  const double f = kWgs84Flattening;
  return on_ellipsoid * (1.0 - 2.0 / a * (1.0 + f + kGravityRatioM - 2.0 * f * s2) * height_m +
                         3.0 * height_m * height_m / (a * a));
}

Eigen::Vector3d earth_rate_enu_rad_s(EarthModel model, double latitude_rad) {
  if (model == EarthModel::kSphereNonRotating) return Eigen::Vector3d::Zero();
  return kWgs84EarthRate_rad_s *
         Eigen::Vector3d(0.0, std::cos(latitude_rad), std::sin(latitude_rad));
}

}  // namespace emulator
}  // namespace imu_lab
