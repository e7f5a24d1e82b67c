#include "imu_lab/nav/earth_model.h"

#include <cmath>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace nav {

namespace {
bool is_sphere(const EarthModelConfig& config) { return config.shape == EarthShape::kSphereNonRotating; }
}  // namespace

EarthModel::EarthModel(const EarthModelConfig& config) : config_(config) {
  if (is_sphere(config_)) {
    if (!(config_.sphere_radius_m > 0.0)) {
      throw ConfigError("nav", "earth.sphere_radius_m", "must be a positive radius in metres");
    }
    if (!(config_.sphere_surface_gravity_m_s2 > 0.0)) {
      throw ConfigError("nav", "earth.sphere_surface_gravity_m_s2", "must be a positive acceleration in m/s^2");
    }
  }
}

double EarthModel::gravity_m_s2(double latitude_rad, double height_m) const {
  if (is_sphere(config_)) {
    const double g0 = config_.sphere_surface_gravity_m_s2;
    if (config_.sphere_gravity_law == SphereGravityLaw::kConstant) return g0;
    const double ratio = config_.sphere_radius_m / (config_.sphere_radius_m + height_m);
    return g0 * ratio * ratio;
  }
  const double sin2 = std::sin(latitude_rad) * std::sin(latitude_rad);
  const double surface = wgs84::kEquatorialGravity_m_s2 * (1.0 + wgs84::kSomiglianaConstant * sin2) /
                         std::sqrt(1.0 - wgs84::kEccentricitySquared * sin2);
  const double a = wgs84::kSemiMajorAxis_m;
  const double f = wgs84::kFlattening;
  const double height_factor = 1.0 - 2.0 / a * (1.0 + f + wgs84::kGravityRatio - 2.0 * f * sin2) * height_m +
                               3.0 * height_m * height_m / (a * a);
  return surface * height_factor;
}

double EarthModel::meridian_radius_m(double latitude_rad) const {
  if (is_sphere(config_)) return config_.sphere_radius_m;
  const double sin2 = std::sin(latitude_rad) * std::sin(latitude_rad);
  const double w = 1.0 - wgs84::kEccentricitySquared * sin2;
  return wgs84::kSemiMajorAxis_m * (1.0 - wgs84::kEccentricitySquared) / (w * std::sqrt(w));
}

double EarthModel::prime_vertical_radius_m(double latitude_rad) const {
  if (is_sphere(config_)) return config_.sphere_radius_m;
  const double sin2 = std::sin(latitude_rad) * std::sin(latitude_rad);
  return wgs84::kSemiMajorAxis_m / std::sqrt(1.0 - wgs84::kEccentricitySquared * sin2);
}

double EarthModel::earth_rate_rad_s() const { return is_sphere(config_) ? 0.0 : wgs84::kEarthRate_rad_s; }

Eigen::Vector3d EarthModel::earth_rate_enu_rad_s(double latitude_rad) const {
  const double rate = earth_rate_rad_s();
  return Eigen::Vector3d(0.0, rate * std::cos(latitude_rad), rate * std::sin(latitude_rad));
}

Eigen::Vector3d EarthModel::transport_rate_enu_rad_s(const Eigen::Vector3d& velocity_enu_m_s, double latitude_rad,
                                                     double height_m) const {
  const double east_radius = prime_vertical_radius_m(latitude_rad) + height_m;
  const double north_radius = meridian_radius_m(latitude_rad) + height_m;
  return Eigen::Vector3d(-velocity_enu_m_s.y() / north_radius, velocity_enu_m_s.x() / east_radius,
                         velocity_enu_m_s.x() * std::tan(latitude_rad) / east_radius);
}

double EarthModel::schuler_rate_rad_s() const {
  return std::sqrt(gravity_m_s2(0.0, 0.0) / prime_vertical_radius_m(0.0));
}

}  // namespace nav
}  // namespace imu_lab
