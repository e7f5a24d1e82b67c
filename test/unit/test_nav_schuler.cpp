// Horizontal error propagation of a static strapdown system on the textbook's non-rotating
// sphere (R = 6371 km, g = 9.81), height held, one error source at a time, against the closed
// forms of Fomichev 2022 eqs. 20, 22, 23. The 3-D linearised errors on a non-rotating sphere decouple
// into two identical Schuler channels (east: d(dv_E)/dt = -g phi_N + b_E, d(phi_N)/dt = dv_E/R -
// e_N; north: d(dv_N)/dt = g phi_E + b_N, d(phi_E)/dt = -dv_N/R - e_E), so with w0 = sqrt(g/R):
//   accelerometer bias b (ENU, horizontal part):  dr = b / w0^2 (1 - cos w0 t)
//   gyro bias e (ENU):                             dr = R (e_N, -e_E) (t - sin(w0 t) / w0)
//   initial velocity error dv0:                    dr = dv0 sin(w0 t) / w0
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>

#include "test_nav_support.h"

namespace imu_lab {
namespace nav {
namespace {

using test_support::ErrorSample;
using test_support::kDegToRad;
using test_support::StaticScenario;

StaticScenario heldSphereScenario(double duration_s) {
  StaticScenario scenario;
  scenario.config.earth = test_support::textbookSphere();
  scenario.config.vertical.mode = VerticalChannelMode::kHeld;
  scenario.config.vertical.fixed_reference_height_m = 0.0;
  // A yawed body, so the test also covers projecting body errors into ENU.
  scenario.q_body_to_enu = Eigen::Quaterniond(Eigen::AngleAxisd(30.0 * kDegToRad, Eigen::Vector3d::UnitZ()));
  scenario.duration_s = duration_s;
  return scenario;
}

double schulerRate() { return EarthModel(test_support::textbookSphere()).schuler_rate_rad_s(); }
double schulerPeriod_s() { return 2.0 * M_PI / schulerRate(); }

// Every sample's horizontal error within tolerance_fraction of the formula's peak over the run.
void expectHorizontalErrorFollows(const std::vector<ErrorSample>& samples,
                                  const std::function<Eigen::Vector2d(double)>& formula_m, double tolerance_fraction,
                                  const char* label) {
  double formula_peak_m = 0.0, measured_peak_m = 0.0, worst_deviation_m = 0.0;
  for (const ErrorSample& s : samples) {
    formula_peak_m = std::max(formula_peak_m, formula_m(s.time_s).norm());
    measured_peak_m = std::max(measured_peak_m, s.position_error_enu_m.head<2>().norm());
  }
  for (const ErrorSample& s : samples) {
    const double deviation_m = (s.position_error_enu_m.head<2>() - formula_m(s.time_s)).norm();
    worst_deviation_m = std::max(worst_deviation_m, deviation_m);
    ASSERT_LE(deviation_m, tolerance_fraction * formula_peak_m)
        << label << " at t = " << s.time_s << " s: simulated (" << s.position_error_enu_m.head<2>().transpose()
        << ") m, formula (" << formula_m(s.time_s).transpose() << ") m";
  }
  std::printf("[nav] %s: peak simulated %.1f m, formula %.1f m, worst deviation %.2f m (%.3f %% of peak)\n", label,
              measured_peak_m, formula_peak_m, worst_deviation_m, 100.0 * worst_deviation_m / formula_peak_m);
}

TEST(NavSchuler, AccelerometerBiasGivesBoundedOneMinusCosine) {
  StaticScenario scenario = heldSphereScenario(1.5 * schulerPeriod_s());
  scenario.accel_bias_body_m_s2 = Eigen::Vector3d(1e-3, 0.0, 0.0);
  const Eigen::Vector2d bias_enu = (scenario.q_body_to_enu * scenario.accel_bias_body_m_s2).head<2>();
  const double w0 = schulerRate();
  const auto formula = [&](double t) -> Eigen::Vector2d { return bias_enu / (w0 * w0) * (1.0 - std::cos(w0 * t)); };
  expectHorizontalErrorFollows(runStaticScenario(scenario), formula, 0.02, "accel bias 1e-3 m/s^2");
  EXPECT_NEAR(2.0 * 1e-3 / (w0 * w0), 1298.9, 0.5);  // the textbook's oracle for the peak
}

TEST(NavSchuler, PeriodMeasuredFromVelocityErrorZeroCrossings) {
  StaticScenario scenario = heldSphereScenario(2.2 * schulerPeriod_s());
  scenario.accel_bias_body_m_s2 = Eigen::Vector3d(1e-3, 0.0, 0.0);
  scenario.sample_every_s = scenario.dt_s;
  const Eigen::Vector3d direction = scenario.q_body_to_enu * Eigen::Vector3d::UnitX();
  const std::vector<ErrorSample> samples = runStaticScenario(scenario);
  std::vector<double> crossings_s;
  for (size_t i = 1; i < samples.size(); ++i) {
    const double before = samples[i - 1].velocity_error_enu_m_s.dot(direction);
    const double after = samples[i].velocity_error_enu_m_s.dot(direction);
    if ((before > 0.0) != (after > 0.0)) {
      const double t0 = samples[i - 1].time_s, t1 = samples[i].time_s;
      crossings_s.push_back(t0 + (t1 - t0) * before / (before - after));
    }
  }
  ASSERT_GE(crossings_s.size(), 3u) << "expected zero crossings near T0/2, T0, 3 T0/2, 2 T0";
  const double period_s = 2.0 * (crossings_s.back() - crossings_s.front()) / (crossings_s.size() - 1);
  std::printf("[nav] Schuler period from %zu zero crossings: %.2f s = %.3f min (2 pi / w0 = %.2f s)\n",
              crossings_s.size(), period_s, period_s / 60.0, schulerPeriod_s());
  EXPECT_NEAR(period_s / 60.0, 84.4, 0.005 * 84.4);
  EXPECT_NEAR(period_s, schulerPeriod_s(), 0.001 * schulerPeriod_s());
}

TEST(NavSchuler, HorizontalGyroDriftGivesRampWithSchulerRipple) {
  StaticScenario scenario = heldSphereScenario(2.0 * 3600.0);
  const double drift_rad_s = 0.01 * test_support::kDegPerHourToRadPerSecond;
  scenario.gyro_bias_body_rad_s = Eigen::Vector3d(0.0, drift_rad_s, 0.0);  // horizontal axis
  const Eigen::Vector3d drift_enu = scenario.q_body_to_enu * scenario.gyro_bias_body_rad_s;
  const double w0 = schulerRate();
  const double radius_m = EarthModel(test_support::textbookSphere()).meridian_radius_m(0.0);
  const auto formula = [&](double t) -> Eigen::Vector2d {
    return radius_m * Eigen::Vector2d(drift_enu.y(), -drift_enu.x()) * (t - std::sin(w0 * t) / w0);
  };
  expectHorizontalErrorFollows(runStaticScenario(scenario), formula, 0.02, "gyro drift 0.01 deg/h");
  EXPECT_NEAR(radius_m * drift_rad_s * 3600.0, 1112.0, 1.0);  // secular growth, m per hour
}

TEST(NavSchuler, InitialVelocityErrorGivesSine) {
  StaticScenario scenario = heldSphereScenario(1.5 * schulerPeriod_s());
  const Eigen::Vector2d velocity_error(1.0, 0.0);
  scenario.initial_velocity_error_enu_m_s << velocity_error, 0.0;
  const double w0 = schulerRate();
  const auto formula = [&](double t) -> Eigen::Vector2d { return velocity_error * std::sin(w0 * t) / w0; };
  expectHorizontalErrorFollows(runStaticScenario(scenario), formula, 0.02, "initial velocity 1 m/s");
}

}  // namespace
}  // namespace nav
}  // namespace imu_lab
