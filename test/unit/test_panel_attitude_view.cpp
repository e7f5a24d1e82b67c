// The attitude panel's logic: angles in degrees, the alignment's ENU sigmas as roll, pitch and yaw
// sigmas, their formatting, and stale sources.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "imu_lab/panel/attitude_view.h"

namespace imu_lab {
namespace panel {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = M_PI / 180.0;
constexpr double kArcsec = kDeg / 3600.0;

AlignmentSummary gyrocompass(double east_rad, double north_rad, double heading_rad) {
  AlignmentSummary alignment;
  alignment.method = "gyrocompass";
  alignment.duration_s = 120.0;
  alignment.error_sigma_enu_rad = {east_rad, north_rad, heading_rad};
  return alignment;
}

TEST(PanelAttitudeView, SigmasFollowTheHeading) {
  const std::array<double, 3> enu{1.0e-4, 3.0e-4, 2.0e-3};
  // Facing east the body's forward axis is east: roll's error is the east tilt.
  auto sigma = roll_pitch_yaw_sigma_rad(enu, 0.0);
  EXPECT_NEAR(sigma[0], 1.0e-4, 1e-15);
  EXPECT_NEAR(sigma[1], 3.0e-4, 1e-15);
  EXPECT_EQ(sigma[2], 2.0e-3);
  // Facing north: forward is north, left is west.
  sigma = roll_pitch_yaw_sigma_rad(enu, M_PI / 2);
  EXPECT_NEAR(sigma[0], 3.0e-4, 1e-15);
  EXPECT_NEAR(sigma[1], 1.0e-4, 1e-15);
  // At 45 deg both tilts share both angles equally.
  sigma = roll_pitch_yaw_sigma_rad(enu, M_PI / 4);
  EXPECT_NEAR(sigma[0], std::sqrt((1.0e-8 + 9.0e-8) / 2), 1e-15);
  EXPECT_NEAR(sigma[1], sigma[0], 1e-15);
  // An angle the method does not estimate stays NaN.
  sigma = roll_pitch_yaw_sigma_rad({1.0e-4, 1.0e-4, kNaN}, 0.3);
  EXPECT_TRUE(std::isnan(sigma[2]));
  EXPECT_NEAR(sigma[0], 1.0e-4, 1e-15);
}

TEST(PanelAttitudeView, FormatsDegreesAndArcseconds) {
  EXPECT_EQ(format_angle_deg(12.3456 * kDeg), "12.346 deg");
  EXPECT_EQ(format_angle_deg(-0.5 * kDeg), "-0.500 deg");
  EXPECT_EQ(format_angle_deg(kNaN), "not finite");
  EXPECT_EQ(format_sigma(4.3 * kArcsec), "+-0.0012 deg (4.3 arcsec)");
  EXPECT_EQ(format_sigma(2.0 * kDeg), "+-2 deg (7200 arcsec)");
  EXPECT_EQ(format_sigma(470.0 * kArcsec), "+-0.13 deg (470 arcsec)");
  EXPECT_EQ(format_sigma(kNaN), "not estimated");
}

TEST(PanelAttitudeView, RowsBeforeAndAfterTheSolution) {
  AttitudePanelModel model(3.0);
  AttitudeView view = model.view(0.0);
  ASSERT_EQ(view.rows.size(), 3u);
  EXPECT_EQ(view.rows[0].angle, "roll");
  EXPECT_EQ(view.rows[2].value, "-");
  EXPECT_EQ(view.rows[2].sigma, "no alignment yet");
  EXPECT_NE(view.solution_line.find("waiting for nav/odometry"), std::string::npos);
  EXPECT_EQ(view.worst_health_level, -1);
  EXPECT_FALSE(view.have_attitude);
  EXPECT_FALSE(view.have_alignment);

  model.set_alignment(gyrocompass(10.0 * kArcsec, 20.0 * kArcsec, kNaN));
  model.set_attitude({1.0 * kDeg, -2.0 * kDeg, 90.0 * kDeg}, 10.0);
  view = model.view(11.0);
  EXPECT_TRUE(view.have_attitude && view.have_alignment);
  EXPECT_EQ(view.rows[0].value, "1.000 deg");
  EXPECT_EQ(view.rows[1].value, "-2.000 deg");
  EXPECT_EQ(view.rows[2].value, "90.000 deg");
  // Facing north: roll has the north tilt's sigma.
  EXPECT_EQ(view.rows[0].sigma, "+-0.0056 deg (20 arcsec)");
  EXPECT_EQ(view.rows[1].sigma, "+-0.0028 deg (10 arcsec)");
  EXPECT_EQ(view.rows[2].sigma, "not estimated");
  EXPECT_EQ(view.solution_line, "navigating; 1-sigma predicted by the gyrocompass alignment (120 s)");
}

TEST(PanelAttitudeView, ASilentSolutionIsStale) {
  AttitudePanelModel model(3.0);
  model.set_attitude({0.0, 0.0, 0.0}, 10.0);
  EXPECT_EQ(model.view(13.0).solution_line, "navigating");
  const AttitudeView view = model.view(20.0);
  EXPECT_EQ(view.solution_line, "STALE: no nav/odometry for 10 s; the angles are the last received");
  EXPECT_EQ(view.rows[0].value, "0.000 deg");
}

TEST(PanelAttitudeView, HealthWorstFirstAndStale) {
  AttitudePanelModel model(3.0);
  model.set_health({"strapdown_navigator: strapdown navigation", 0, "navigating"}, 100.0);
  EXPECT_EQ(model.view(100.5).health_summary, "input health: OK (1 status)");
  model.set_health({"allan_monitor: allan", 1, "2 gaps (0.3 s)"}, 100.0);
  AttitudeView view = model.view(101.0);
  EXPECT_EQ(view.health_summary, "input health: WARN (2 statuses)");
  EXPECT_EQ(view.worst_health_level, 1);
  ASSERT_EQ(view.health_lines.size(), 2u);
  EXPECT_EQ(view.health_lines[0].text, "WARN  allan_monitor: allan: 2 gaps (0.3 s)");
  EXPECT_EQ(view.health_lines[0].level, 1);
  EXPECT_EQ(view.health_lines[1].text, "OK  strapdown_navigator: strapdown navigation: navigating");

  // A newer status replaces the older one of the same name; a silent one turns stale.
  model.set_health({"allan_monitor: allan", 0, "ok"}, 104.5);
  view = model.view(105.0);
  EXPECT_EQ(view.worst_health_level, 3);
  EXPECT_EQ(view.health_summary, "input health: STALE (2 statuses)");
  EXPECT_EQ(view.health_lines[0].text,
            "STALE  strapdown_navigator: strapdown navigation: navigating (last report 5 s ago)");
  EXPECT_EQ(view.health_lines[1].text, "OK  allan_monitor: allan: ok");
}

}  // namespace
}  // namespace panel
}  // namespace imu_lab
