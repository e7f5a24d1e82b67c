// Earth model values and the mechanisation's consistency on the rotating WGS-84 Earth.
#include <gtest/gtest.h>

#include <cstdio>

#include "test_nav_support.h"

namespace imu_lab {
namespace nav {
namespace {

using test_support::kDegToRad;

TEST(NavEarthModel, SomiglianaNormalGravity) {
  const EarthModel earth;
  EXPECT_NEAR(earth.gravity_m_s2(0.0, 0.0), 9.7803253359, 1e-10);
  EXPECT_NEAR(earth.gravity_m_s2(90.0 * kDegToRad, 0.0), 9.8321849378, 1e-9);  // g_p of WGS-84
  // Free-air gradient about 3.086e-6 (m/s^2)/m near the surface.
  EXPECT_NEAR(earth.gravity_m_s2(45.0 * kDegToRad, 1000.0) - earth.gravity_m_s2(45.0 * kDegToRad, 0.0), -3.086e-3,
              1e-5);
  EXPECT_NEAR(earth.meridian_radius_m(0.0), 6335439.327, 1e-3);
  EXPECT_NEAR(earth.prime_vertical_radius_m(90.0 * kDegToRad), 6399593.626, 1e-3);
}

TEST(NavEarthModel, TextbookSphere) {
  const EarthModel sphere(test_support::textbookSphere());
  EXPECT_DOUBLE_EQ(sphere.gravity_m_s2(0.3, 0.0), 9.81);
  EXPECT_DOUBLE_EQ(sphere.gravity_m_s2(0.3, 6371000.0), 9.81 / 4.0);
  EXPECT_EQ(sphere.earth_rate_enu_rad_s(0.3), Eigen::Vector3d::Zero());
  EXPECT_NEAR(2.0 * M_PI / sphere.schuler_rate_rad_s() / 60.0, 84.39, 0.01);
}

// A perfect static IMU on the rotating ellipsoid: Earth rate, normal gravity, curvature and the
// nav-frame rotation must cancel exactly, with the vertical channel free.
TEST(NavRotatingEarth, PerfectStaticImuStaysPut) {
  test_support::StaticScenario scenario;
  scenario.config.vertical.mode = VerticalChannelMode::kFree;
  scenario.latitude_rad = 50.0 * kDegToRad;
  scenario.q_body_to_enu = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()));
  scenario.duration_s = 3600.0;
  scenario.dt_s = 0.1;
  for (const test_support::ErrorSample& s : runStaticScenario(scenario)) {
    ASSERT_LT(s.position_error_enu_m.norm(), 1e-4) << "t = " << s.time_s;
    ASSERT_LT(s.attitude_error_rad.norm(), 1e-10) << "t = " << s.time_s;
  }
}

// Coriolis: on the rotating Earth the Schuler oscillation's plane turns like Foucault's pendulum,
// clockwise seen from above in the north. For an initial velocity error dv0 and w_F = W sin L,
// z = dr_E + i dr_N obeys z'' + 2 i w_F z' + w0^2 z = 0, so z = dv0 exp(-i w_F t) sin(w_s t) / w_s,
// w_s = sqrt(w0^2 + w_F^2) (neglecting the 24-h coupling, small over 1.5 h).
TEST(NavRotatingEarth, SchulerOscillationTurnsAtTheFoucaultRate) {
  test_support::StaticScenario scenario;
  scenario.config.vertical.fixed_reference_height_m = 0.0;
  scenario.latitude_rad = 50.0 * kDegToRad;
  const EarthModel earth;
  const double w0_squared =
      earth.gravity_m_s2(scenario.latitude_rad, 0.0) /
      std::sqrt(earth.meridian_radius_m(scenario.latitude_rad) * earth.prime_vertical_radius_m(scenario.latitude_rad));
  const double foucault_rate = earth.earth_rate_rad_s() * std::sin(scenario.latitude_rad);
  const double schuler_rate = std::sqrt(w0_squared + foucault_rate * foucault_rate);
  scenario.duration_s = 1.5 * 2.0 * M_PI / schuler_rate;
  scenario.initial_velocity_error_enu_m_s = Eigen::Vector3d(1.0, 0.0, 0.0);
  double worst_m = 0.0, peak_m = 1.0 / schuler_rate;
  double quarter_period_angle_rad = 0.0;
  for (const test_support::ErrorSample& s : runStaticScenario(scenario)) {
    const double amplitude_m = std::sin(schuler_rate * s.time_s) / schuler_rate;
    const Eigen::Vector2d expected(amplitude_m * std::cos(foucault_rate * s.time_s),
                                   -amplitude_m * std::sin(foucault_rate * s.time_s));
    worst_m = std::max(worst_m, (s.position_error_enu_m.head<2>() - expected).norm());
    if (std::abs(s.time_s - std::round(0.25 * 2.0 * M_PI / schuler_rate / 60.0) * 60.0) < 1.0) {
      quarter_period_angle_rad = std::atan2(s.position_error_enu_m.y(), s.position_error_enu_m.x());
    }
  }
  std::printf(
      "[nav] Foucault: error direction at T0/4 turned %.4f rad (expected %.4f), worst deviation "
      "%.1f m of %.1f m peak\n",
      quarter_period_angle_rad, -foucault_rate * 0.25 * 2.0 * M_PI / schuler_rate, worst_m, peak_m);
  EXPECT_LE(worst_m, 0.02 * peak_m);
  EXPECT_NEAR(quarter_period_angle_rad, -foucault_rate * 0.25 * 2.0 * M_PI / schuler_rate, 0.005);
}

// Level flight at constant ENU velocity over the ellipsoid, body axes = ENU: the body turns at
// w_ie + w_en and feels f = (2 w_ie + w_en) x v + (0, 0, g). Increments are Simpson integrals of
// these along an RK4 truth trajectory (dL/dt = v_N / R_M, dlon/dt = v_E / (R_N cos L)); the
// navigator must follow the truth: this checks the radii, transport rate and Coriolis together.
TEST(NavRotatingEarth, ConstantVelocityFlightFollowsTheEllipsoid) {
  const EarthModel earth;
  const Eigen::Vector3d velocity_enu(50.0, 100.0, 0.0);
  const double dt_s = 0.1, duration_s = 3600.0;
  const auto position_rate = [&](const Eigen::Vector2d& latitude_longitude) {
    const double latitude = latitude_longitude.x();
    return Eigen::Vector2d(velocity_enu.y() / earth.meridian_radius_m(latitude),
                           velocity_enu.x() / (earth.prime_vertical_radius_m(latitude) * std::cos(latitude)));
  };
  const auto body_rate = [&](double latitude) {
    return (earth.earth_rate_enu_rad_s(latitude) + earth.transport_rate_enu_rad_s(velocity_enu, latitude, 0.0)).eval();
  };
  const auto specific_force = [&](double latitude) {
    const Eigen::Vector3d coriolis_rate =
        2.0 * earth.earth_rate_enu_rad_s(latitude) + earth.transport_rate_enu_rad_s(velocity_enu, latitude, 0.0);
    return (coriolis_rate.cross(velocity_enu) + Eigen::Vector3d(0.0, 0.0, earth.gravity_m_s2(latitude, 0.0))).eval();
  };

  NavigatorConfig config;
  config.vertical.fixed_reference_height_m = 0.0;
  Navigator navigator(config);
  NavState truth;
  truth.latitude_rad = 50.0 * kDegToRad;
  truth.longitude_rad = 10.0 * kDegToRad;
  truth.velocity_enu_m_s = velocity_enu;
  navigator.initialise(truth);
  Eigen::Vector2d position(truth.latitude_rad, truth.longitude_rad);
  const double half_step = 0.5 * dt_s;
  const long steps = std::lround(duration_s / dt_s);
  for (long k = 0; k < steps; ++k) {
    ImuIncrement increment;
    increment.dt_s = dt_s;
    const double latitude_start = position.x();
    double latitude_mid = 0.0;
    for (int half = 0; half < 2; ++half) {  // RK4 over each half step
      const Eigen::Vector2d k1 = position_rate(position);
      const Eigen::Vector2d k2 = position_rate(position + 0.5 * half_step * k1);
      const Eigen::Vector2d k3 = position_rate(position + 0.5 * half_step * k2);
      const Eigen::Vector2d k4 = position_rate(position + half_step * k3);
      position += half_step / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      if (half == 0) latitude_mid = position.x();
    }
    increment.delta_angle_rad =
        dt_s / 6.0 * (body_rate(latitude_start) + 4.0 * body_rate(latitude_mid) + body_rate(position.x()));
    increment.delta_velocity_m_s =
        dt_s / 6.0 *
        (specific_force(latitude_start) + 4.0 * specific_force(latitude_mid) + specific_force(position.x()));
    navigator.update(increment);
  }
  truth.latitude_rad = position.x();
  truth.longitude_rad = position.y();
  const Eigen::Vector3d error_m = test_support::positionErrorEnu_m(earth, navigator.state(), truth);
  const double distance_m = velocity_enu.norm() * duration_s;
  std::printf(
      "[nav] WGS-84 flight, %.0f km in 1 h: position error (E N U) %.3f %.3f %.3f m, velocity "
      "error %.2e m/s\n",
      distance_m / 1000.0, error_m.x(), error_m.y(), error_m.z(),
      (navigator.state().velocity_enu_m_s - velocity_enu).norm());
  EXPECT_LT(error_m.norm(), 0.1);
  EXPECT_LT((navigator.state().velocity_enu_m_s - velocity_enu).norm(), 1e-4);
  EXPECT_LT(test_support::attitudeError_rad(navigator.state().q_body_to_enu, truth.q_body_to_enu).norm(), 1e-8);
}

}  // namespace
}  // namespace nav
}  // namespace imu_lab
