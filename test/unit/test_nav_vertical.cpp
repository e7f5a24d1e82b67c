// Vertical channel on the textbook sphere (gravity R^2 / (R + h)^2), static IMU at the true height
// 0. Free: dh'' = 2 w0^2 dh + b (Fomichev 2022 eq. 32), so
//   initial height error e0:  dh = e0 cosh(sqrt(2) w0 t)
//   vertical accel bias b:    dh = b / (2 w0^2) (cosh(sqrt(2) w0 t) - 1)
// Held (eq. 34, gains k1, k2, a = k2 + 2 w0^2 < 0): dh stays within |e0| + |b| / |a| and tends to
// -b / a.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>

#include "test_nav_support.h"

namespace imu_lab {
namespace nav {
namespace {

using test_support::ErrorSample;
using test_support::StaticScenario;

StaticScenario sphereScenario(VerticalChannelMode mode, double duration_s) {
  StaticScenario scenario;
  scenario.config.earth = test_support::textbookSphere();
  scenario.config.vertical.mode = mode;
  scenario.config.vertical.fixed_reference_height_m = 0.0;
  scenario.duration_s = duration_s;
  scenario.sample_every_s = 100.0;
  return scenario;
}

double schulerRate() { return EarthModel(test_support::textbookSphere()).schuler_rate_rad_s(); }

// Relative agreement with a closed form at every sample; returns the worst relative deviation.
double expectHeightErrorFollows(const std::vector<ErrorSample>& samples, const std::function<double(double)>& formula_m,
                                double tolerance) {
  double worst = 0.0;
  for (const ErrorSample& s : samples) {
    const double expected = formula_m(s.time_s);
    const double relative = std::abs(s.position_error_enu_m.z() - expected) / std::abs(expected);
    worst = std::max(worst, relative);
    EXPECT_LE(relative, tolerance) << "t = " << s.time_s << " s: simulated " << s.position_error_enu_m.z()
                                   << " m, formula " << expected << " m";
  }
  return worst;
}

TEST(NavVertical, FreeHeightErrorGrowsAsCosh) {
  StaticScenario scenario = sphereScenario(VerticalChannelMode::kFree, 3000.0);
  scenario.initial_height_error_m = 10.0;
  const double rate = std::sqrt(2.0) * schulerRate();
  const std::vector<ErrorSample> samples = runStaticScenario(scenario);
  const double worst = expectHeightErrorFollows(
      samples, [&](double t) { return 10.0 * std::cosh(rate * t); }, 0.02);
  std::printf(
      "[nav] free vertical, 10 m initial error: %.1f m after %.0f s (formula %.1f m), worst "
      "deviation %.3f %%; e-folding time %.1f s\n",
      samples.back().position_error_enu_m.z(), samples.back().time_s, 10.0 * std::cosh(rate * samples.back().time_s),
      100.0 * worst, 1.0 / rate);
}

TEST(NavVertical, FreeAccelerometerBiasGrowsAsCoshMinusOne) {
  StaticScenario scenario = sphereScenario(VerticalChannelMode::kFree, 3000.0);
  const double bias_m_s2 = 1e-4;
  scenario.accel_bias_body_m_s2 = Eigen::Vector3d(0.0, 0.0, bias_m_s2);
  const double w0 = schulerRate();
  const double worst = expectHeightErrorFollows(
      runStaticScenario(scenario),
      [&](double t) { return bias_m_s2 / (2.0 * w0 * w0) * (std::cosh(std::sqrt(2.0) * w0 * t) - 1.0); }, 0.02);
  std::printf("[nav] free vertical, 1e-4 m/s^2 up bias: worst deviation from closed form %.3f %%\n", 100.0 * worst);
}

TEST(NavVertical, ConstantGravityLawHasNoDivergence) {
  StaticScenario scenario = sphereScenario(VerticalChannelMode::kFree, 3000.0);
  scenario.config.earth.sphere_gravity_law = SphereGravityLaw::kConstant;
  scenario.initial_height_error_m = 10.0;
  for (const ErrorSample& s : runStaticScenario(scenario)) {
    ASSERT_NEAR(s.position_error_enu_m.z(), 10.0, 1e-6) << "t = " << s.time_s;
  }
}

TEST(NavVertical, HeldChannelStaysWithinDerivedBound) {
  StaticScenario scenario = sphereScenario(VerticalChannelMode::kHeld, 7200.0);
  scenario.sample_every_s = 1.0;
  scenario.initial_height_error_m = 10.0;
  const double bias_m_s2 = 1e-3;
  scenario.accel_bias_body_m_s2 = Eigen::Vector3d(0.0, 0.0, bias_m_s2);
  const double w0 = schulerRate();
  const double loop_stiffness = scenario.config.vertical.k2_per_s2 + 2.0 * w0 * w0;  // a < 0
  const double steady_state_m = -bias_m_s2 / loop_stiffness;
  const double bound_m = 10.0 + std::abs(steady_state_m);
  double worst_m = 0.0;
  const std::vector<ErrorSample> samples = runStaticScenario(scenario);
  for (const ErrorSample& s : samples) worst_m = std::max(worst_m, std::abs(s.position_error_enu_m.z()));
  std::printf(
      "[nav] held vertical, 10 m initial error + 1e-3 m/s^2 bias: max |dh| %.3f m <= bound %.3f m, "
      "final %.4f m (steady state -b/(k2+2w0^2) = %.4f m)\n",
      worst_m, bound_m, samples.back().position_error_enu_m.z(), steady_state_m);
  EXPECT_LE(worst_m, bound_m);
  EXPECT_NEAR(samples.back().position_error_enu_m.z(), steady_state_m, 0.01 * steady_state_m);
}

TEST(NavVertical, ReferenceFedLaterPullsFreeChannelBack) {
  NavigatorConfig config;
  config.earth = test_support::textbookSphere();
  config.vertical.mode = VerticalChannelMode::kHeld;  // no fixed reference: free until one arrives
  Navigator navigator(config);
  NavState truth;
  truth.latitude_rad = 0.3;
  NavState initial = truth;
  initial.height_m = 10.0;
  navigator.initialise(initial);
  const ImuIncrement increment =
      test_support::staticImuIncrement(navigator.earth(), truth.q_body_to_enu, truth.latitude_rad, 0.0, 1.0);
  for (int step = 0; step < 600; ++step) navigator.update(increment);
  const double free_error_m = navigator.state().height_m;
  EXPECT_GT(free_error_m, 10.0 * std::cosh(std::sqrt(2.0) * schulerRate() * 600.0) * 0.98);
  navigator.set_reference_height(0.0);
  for (int step = 0; step < 600; ++step) navigator.update(increment);  // 20 loop time constants
  EXPECT_LT(std::abs(navigator.state().height_m), 1e-3 * free_error_m);
  navigator.clear_reference_height();  // prediction mode again: nothing pulls it any more
  navigator.initialise(initial);
  for (int step = 0; step < 600; ++step) navigator.update(increment);
  EXPECT_NEAR(navigator.state().height_m, free_error_m, 1e-9 * free_error_m);
}

}  // namespace
}  // namespace nav
}  // namespace imu_lab
