// Shared fixtures for the nav tests: ideal IMU increments of a static IMU, error measures, and a
// runner for static error-propagation scenarios.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "imu_lab/nav/earth_model.h"
#include "imu_lab/nav/navigator.h"
#include "imu_lab/nav/rotation.h"

namespace imu_lab {
namespace nav {
namespace test_support {

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kDegPerHourToRadPerSecond = kDegToRad / 3600.0;

inline EarthModelConfig textbookSphere() {
  EarthModelConfig config;
  config.shape = EarthShape::kSphereNonRotating;
  return config;
}

// Exact increments of an IMU at rest on the Earth: it turns with the Earth and feels normal
// gravity upwards.
inline ImuIncrement staticImuIncrement(const EarthModel& earth, const Eigen::Quaterniond& q_body_to_enu,
                                       double latitude_rad, double height_m, double dt_s) {
  const Eigen::Quaterniond enu_to_body = q_body_to_enu.conjugate();
  ImuIncrement increment;
  increment.delta_angle_rad = enu_to_body * earth.earth_rate_enu_rad_s(latitude_rad) * dt_s;
  increment.delta_velocity_m_s =
      enu_to_body * Eigen::Vector3d(0.0, 0.0, earth.gravity_m_s2(latitude_rad, height_m)) * dt_s;
  increment.dt_s = dt_s;
  return increment;
}

// (east, north, up) position error in metres of an estimate against the truth.
inline Eigen::Vector3d positionErrorEnu_m(const EarthModel& earth, const NavState& estimate, const NavState& truth) {
  const double latitude = truth.latitude_rad;
  const double longitude_error = std::remainder(estimate.longitude_rad - truth.longitude_rad, 2.0 * M_PI);
  return Eigen::Vector3d(
      longitude_error * (earth.prime_vertical_radius_m(latitude) + truth.height_m) * std::cos(latitude),
      (estimate.latitude_rad - latitude) * (earth.meridian_radius_m(latitude) + truth.height_m),
      estimate.height_m - truth.height_m);
}

// Small rotation delta (nav axes) with estimate = exp(delta) * truth.
inline Eigen::Vector3d attitudeError_rad(const Eigen::Quaterniond& estimate, const Eigen::Quaterniond& truth) {
  return rotation_vector_from_quaternion(estimate * truth.conjugate());
}

// A static IMU with constant sensor errors, navigated from a (possibly wrong) initial state.
struct StaticScenario {
  NavigatorConfig config;
  Eigen::Quaterniond q_body_to_enu = Eigen::Quaterniond::Identity();
  double latitude_rad = 45.0 * kDegToRad;
  double longitude_rad = 10.0 * kDegToRad;
  Eigen::Vector3d accel_bias_body_m_s2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_bias_body_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d initial_velocity_error_enu_m_s = Eigen::Vector3d::Zero();
  double initial_height_error_m = 0.0;
  double dt_s = 1.0;
  double duration_s = 0.0;
  double sample_every_s = 60.0;
};

struct ErrorSample {
  double time_s;
  Eigen::Vector3d position_error_enu_m;
  Eigen::Vector3d velocity_error_enu_m_s;
  Eigen::Vector3d attitude_error_rad;
};

// Truth is at height 0; a held vertical channel (if configured) holds it there.
inline std::vector<ErrorSample> runStaticScenario(const StaticScenario& scenario) {
  Navigator navigator(scenario.config);
  NavState truth;
  truth.q_body_to_enu = scenario.q_body_to_enu;
  truth.latitude_rad = scenario.latitude_rad;
  truth.longitude_rad = scenario.longitude_rad;
  NavState initial = truth;
  initial.velocity_enu_m_s += scenario.initial_velocity_error_enu_m_s;
  initial.height_m += scenario.initial_height_error_m;
  navigator.initialise(initial);

  ImuIncrement increment =
      staticImuIncrement(navigator.earth(), scenario.q_body_to_enu, truth.latitude_rad, truth.height_m, scenario.dt_s);
  increment.delta_angle_rad += scenario.gyro_bias_body_rad_s * scenario.dt_s;
  increment.delta_velocity_m_s += scenario.accel_bias_body_m_s2 * scenario.dt_s;

  std::vector<ErrorSample> samples;
  const long steps = std::lround(scenario.duration_s / scenario.dt_s);
  const long steps_per_sample = std::max(1L, std::lround(scenario.sample_every_s / scenario.dt_s));
  for (long step = 1; step <= steps; ++step) {
    const NavState& state = navigator.update(increment);
    if (step % steps_per_sample != 0) continue;
    samples.push_back({state.stamp_s, positionErrorEnu_m(navigator.earth(), state, truth),
                       state.velocity_enu_m_s - truth.velocity_enu_m_s,
                       attitudeError_rad(state.q_body_to_enu, truth.q_body_to_enu)});
  }
  return samples;
}

}  // namespace test_support
}  // namespace nav
}  // namespace imu_lab
