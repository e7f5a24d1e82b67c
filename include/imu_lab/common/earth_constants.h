// The Earth the emulator and the navigator agree on by definition: which shape, and each shape's
// constants. Each computes gravity, radii and rates from them on its own (doc/models.md): the
// emulator's kinematics is the navigator's oracle, so only the constants are shared, never the
// formulas.
#pragma once

namespace imu_lab {

enum class EarthShape {
  kWgs84Rotating,      // WGS-84 ellipsoid, Somigliana normal gravity with its height terms, Earth rate
  kSphereNonRotating,  // the textbook sphere below, fixed in inertial space [Fomichev 2022, §1.1]
};

// WGS-84 defining and derived constants [WGS-84, tables 3.1-3.3].
namespace wgs84 {
constexpr double kSemiMajorAxis_m = 6378137.0;
constexpr double kFlattening = 1.0 / 298.257223563;
constexpr double kEccentricitySquared = kFlattening * (2.0 - kFlattening);
constexpr double kEarthRate_rad_s = 7.292115e-5;
constexpr double kEquatorialGravity_m_s2 = 9.7803253359;
constexpr double kSomiglianaConstant = 0.00193185265241;  // k = (b g_p - a g_e) / (a g_e)
constexpr double kGravityRatio = 0.00344978650684;        // m = w^2 a^2 b / GM
}  // namespace wgs84

// The textbook's non-rotating sphere: radius 6371 km, 9.81 m/s^2 at the surface.
namespace textbook_sphere {
constexpr double kRadius_m = 6371000.0;
constexpr double kSurfaceGravity_m_s2 = 9.81;
}  // namespace textbook_sphere

}  // namespace imu_lab
