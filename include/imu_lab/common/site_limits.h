// Where an inertial sensor can be: the ranges every site (a tool's option, a node's parameter)
// is checked against, so that a height of 1e12 m or a longitude of 1e6 deg is refused as bad
// configuration instead of navigated or fitted.
#pragma once

namespace imu_lab {
namespace site_limits {

constexpr double kLowestHeightM = -11000.0;   // the deepest ocean trench
constexpr double kHighestHeightM = 100000.0;  // the edge of space (Karman line)
constexpr double kLowestLongitudeDeg = -180.0;
constexpr double kHighestLongitudeDeg = 360.0;  // east-only longitudes, 0 .. 360, are common too

}  // namespace site_limits
}  // namespace imu_lab
