// Scenario truth is self-consistent and exact: increments equal fine integrals of the truth's
// rate and force; the strapdown equations driven by the truth's rate and force reproduce its
// attitude, velocity and position; dwells see exactly gravity and Earth rate; coning is the
// closed-form solution. Bounds (stated in the report): increment error <= 1e-10 rad and
// 1e-9 m/s per sample, attitude <= 1e-9 rad, against the navigation-grade RLG's 1 arcsec
// (4.8e-6 rad) pulses and ARW 0.001 deg/sqrt(h) (2.9e-8 rad per 10 ms sample).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "imu_lab/emulator/earth_model.h"
#include "imu_lab/emulator/piecewise_quadrature.h"
#include "imu_lab/emulator/static_motion.h"
#include "test_emulator_scenario_support.h"

namespace imu_lab {
namespace emulator {
namespace {

using scenario_test::kDeg;

TEST(EmulatorScenarioTruth, QuadratureExactForDegree15AndSplitsAtBreakpoints) {
  auto poly = [](double t) { return std::pow(t, 15) - 3.0 * std::pow(t, 7) + t; };
  const double exact = std::pow(1.3, 16) / 16 - 3.0 * std::pow(1.3, 8) / 8 + 1.3 * 1.3 / 2;
  EXPECT_NEAR(integrate_smooth_pieces(poly, 0.0, 1.3, {}, 10.0, 0.0), exact, 1e-13 * exact);
  // A step at 0.37: exact only because the piece is split there.
  auto step = [](double t) { return t < 0.37 ? 1.0 : 5.0; };
  EXPECT_NEAR(integrate_smooth_pieces(step, 0.0, 1.0, {0.37}, 10.0, 0.0), 0.37 + 5.0 * 0.63, 1e-15);
}

struct TruthCase {
  const char* file;
  EarthShape earth;
  double window_s;             // run this long from the start
  std::vector<double> cuts_s;  // instants where the rate or force jumps (known from the file)
  double max_step_s;           // reference integrator step
};

class EmulatorScenarioTruthCases : public ::testing::TestWithParam<TruthCase> {};

TEST_P(EmulatorScenarioTruthCases, IncrementsEqualFineIntegralsOfTheTruth) {
  const TruthCase& c = GetParam();
  auto motion = make_motion_source(scenario_test::shipped_scenario(c.file, c.earth));
  const double interval_s = 0.01;
  double worst_angle = 0.0, worst_velocity = 0.0;
  const int samples = static_cast<int>(std::lround(std::min(c.window_s, 130.0) / interval_s));
  const int stride = samples > 4000 ? 13 : 1;  // long windows: check every 13th sample (all are run)
  for (int k = 0; k < samples; ++k) {
    const double start = k * interval_s;
    const TruthIncrement increment = motion->increment(start, interval_s);
    if (k % stride) continue;
    const auto [angle, velocity] = scenario_test::simpson_increment(*motion, start, start + interval_s, c.cuts_s, 2000);
    worst_angle = std::max(worst_angle, (increment.delta_angle_rad - angle).norm());
    worst_velocity = std::max(worst_velocity, (increment.delta_velocity_m_s - velocity).norm());
  }
  std::printf("[truth] %s (%s): worst increment error %.2e rad, %.2e m/s per 10 ms sample\n", c.file,
              c.earth == EarthShape::kWgs84Rotating ? "wgs84" : "sphere", worst_angle, worst_velocity);
  EXPECT_LT(worst_angle, 1e-10);
  EXPECT_LT(worst_velocity, 1e-9);
}

TEST_P(EmulatorScenarioTruthCases, StrapdownEquationsReproduceTheTruth) {
  const TruthCase& c = GetParam();
  auto motion = make_motion_source(scenario_test::shipped_scenario(c.file, c.earth));
  const auto errors = scenario_test::integrate_against_truth(*motion, c.earth, c.window_s, c.cuts_s, c.max_step_s);
  std::printf("[truth] %s (%s): RK4 over %.0f s: attitude %.2e rad, velocity %.2e m/s, position %.2e m\n", c.file,
              c.earth == EarthShape::kWgs84Rotating ? "wgs84" : "sphere", c.window_s, errors.attitude_rad,
              errors.velocity_m_s, errors.position_m);
  EXPECT_LT(errors.attitude_rad, 1e-9);
  EXPECT_LT(errors.velocity_m_s, 1e-7);
  EXPECT_LT(errors.position_m, 1e-5);
}

std::vector<double> trajectory_leg_ends() {
  std::vector<double> ends;
  double t = 0.0;
  for (double d : {60.0, 20.0, 30.0, 120.0, 45.0, 100.0, 20.0, 200.0}) ends.push_back(t += d);
  return ends;
}

INSTANTIATE_TEST_SUITE_P(
    Shipped, EmulatorScenarioTruthCases,
    ::testing::Values(
        // 60 s dwell, a 180-degree turn, the next dwell: rate kinks only (no cuts needed).
        TruthCase{"multiposition_6.yaml", EarthShape::kWgs84Rotating, 85.0, {}, 2e-3},
        TruthCase{"multiposition_12_thesis.yaml", EarthShape::kSphereNonRotating, 130.0, {}, 2e-3},
        // +1, -1 and +10 deg/s holds and the changes between them.
        TruthCase{"rate_table.yaml", EarthShape::kWgs84Rotating, 130.0, {}, 2e-3},
        TruthCase{"coning.yaml", EarthShape::kWgs84Rotating, 20.0, {}, 1e-3},
        TruthCase{"coning.yaml", EarthShape::kSphereNonRotating, 5.0, {}, 1e-3},
        TruthCase{"sculling.yaml", EarthShape::kWgs84Rotating, 10.0, {}, 2e-4},
        TruthCase{"trajectory.yaml", EarthShape::kWgs84Rotating, 400.0, trajectory_leg_ends(), 1e-2},
        TruthCase{"trajectory.yaml", EarthShape::kSphereNonRotating, 120.0, trajectory_leg_ends(), 1e-2}));

TEST(EmulatorScenarioTruth, DwellsSeeExactlyGravityAndEarthRateThroughTheirOrientation) {
  for (EarthShape earth : {EarthShape::kWgs84Rotating, EarthShape::kSphereNonRotating}) {
    const ScenarioConfig scenario = scenario_test::shipped_scenario("multiposition_12_thesis.yaml", earth);
    auto motion = make_motion_source(scenario);
    const auto& config = *scenario.multi_position;
    const Eigen::Vector3d earth_rate = earth_rate_enu_rad_s(earth, scenario.latitude_rad);
    const Eigen::Vector3d up_force(0.0, 0.0, normal_gravity_m_s2(earth, scenario.latitude_rad, scenario.height_m));
    double dwell_start = 0.0, worst_rate = 0.0, worst_force = 0.0, worst_attitude = 0.0;
    for (std::size_t i = 0; i < config.positions.size(); ++i) {
      const auto& position = config.positions[i];
      const Eigen::Matrix3d enu_to_body = position.attitude_body_to_enu.toRotationMatrix().transpose();
      // A whole 10 ms sample well inside the dwell.
      const double start = dwell_start + 0.5 * position.dwell_s;
      const TruthIncrement increment = motion->increment(start, 0.01);
      const TruthState truth = motion->truth_at(start);
      worst_rate = std::max({worst_rate, (increment.delta_angle_rad / 0.01 - enu_to_body * earth_rate).norm(),
                             (truth.angular_rate_body_rad_s - enu_to_body * earth_rate).norm()});
      worst_force = std::max({worst_force, (increment.delta_velocity_m_s / 0.01 - enu_to_body * up_force).norm(),
                              (truth.specific_force_body_m_s2 - enu_to_body * up_force).norm()});
      worst_attitude =
          std::max(worst_attitude, truth.attitude_body_to_enu.angularDistance(position.attitude_body_to_enu));
      if (i + 1 == config.positions.size()) break;
      // The move to the next position, timed by the test: trapezoid (or triangle) over the angle.
      const double angle = position.attitude_body_to_enu.angularDistance(config.positions[i + 1].attitude_body_to_enu);
      const double rate = config.move_rate_rad_s, acceleration = config.move_acceleration_rad_s2;
      const double move_s = angle >= rate * rate / acceleration ? angle / rate + rate / acceleration
                                                                : 2.0 * std::sqrt(angle / acceleration);
      dwell_start += position.dwell_s + move_s;
    }
    std::printf(
        "[dwell] 12-position thesis scheme (%s): worst |rate - C^T w_ie| %.1e rad/s, "
        "|force - C^T g| %.1e m/s^2, attitude %.1e rad\n",
        earth == EarthShape::kWgs84Rotating ? "wgs84" : "sphere", worst_rate, worst_force, worst_attitude);
    EXPECT_LT(worst_rate, 1e-18);
    EXPECT_LT(worst_force, 2e-14);
    EXPECT_LT(worst_attitude, 1e-12);
  }
}

TEST(EmulatorScenarioTruth, ThesisSchemePutsEachAxisUpAndDown) {
  const ScenarioConfig scenario = load_scenario(test::config_path("scenarios/multiposition_12_thesis.yaml"));
  Eigen::Vector3d most_up = Eigen::Vector3d::Constant(-1.0), most_down = Eigen::Vector3d::Constant(1.0);
  for (const auto& position : scenario.multi_position->positions) {
    const Eigen::Vector3d up_in_body = position.attitude_body_to_enu.conjugate() * Eigen::Vector3d::UnitZ();
    most_up = most_up.cwiseMax(up_in_body);
    most_down = most_down.cwiseMin(up_in_body);
  }
  EXPECT_LT((most_up - Eigen::Vector3d::Ones()).norm(), 1e-12);
  EXPECT_LT((most_down + Eigen::Vector3d::Ones()).norm(), 1e-12);
}

TEST(EmulatorScenarioTruth, ConingIsTheClosedFormSolution) {
  for (EarthShape earth : {EarthShape::kSphereNonRotating, EarthShape::kWgs84Rotating}) {
    const ScenarioConfig scenario = scenario_test::shipped_scenario("coning.yaml", earth);
    auto motion = make_motion_source(scenario);
    const double a = scenario.coning->half_angle_rad, w = 2.0 * M_PI * scenario.coning->frequency_hz;
    const Eigen::Quaterniond mount = scenario.coning->mount_body_to_enu;
    const Eigen::Vector3d earth_rate = earth_rate_enu_rad_s(earth, scenario.latitude_rad);
    double worst_attitude = 0.0, worst_rate = 0.0;
    for (double t = 0.0; t < 10.0; t += 0.0137) {
      const Eigen::Quaterniond cone(std::cos(a / 2), std::sin(a / 2) * std::cos(w * t),
                                    std::sin(a / 2) * std::sin(w * t), 0.0);
      const Eigen::Vector3d cone_rate(-w * std::sin(a) * std::sin(w * t), w * std::sin(a) * std::cos(w * t),
                                      -2.0 * w * std::sin(a / 2) * std::sin(a / 2));
      const TruthState truth = motion->truth_at(t);
      const Eigen::Quaterniond attitude = mount * cone;
      worst_attitude = std::max(worst_attitude, truth.attitude_body_to_enu.angularDistance(attitude));
      worst_rate =
          std::max(worst_rate, (truth.angular_rate_body_rad_s - cone_rate - attitude.conjugate() * earth_rate).norm());
    }
    // The coning drift: over whole cycles the z increments sum to -2 W sin^2(a/2) T.
    const double cycles_s = 20.0 / scenario.coning->frequency_hz;
    double z_sum = 0.0;
    for (int k = 0; k < static_cast<int>(std::lround(cycles_s / 0.01)); ++k) {
      z_sum += motion->increment(k * 0.01, 0.01).delta_angle_rad.z();
    }
    double z_expected = -2.0 * w * std::sin(a / 2) * std::sin(a / 2) * cycles_s;
    if (earth == EarthShape::kWgs84Rotating) z_expected = std::nan("");  // Earth rate adds to z
    std::printf(
        "[coning] %s: attitude %.1e rad, rate %.1e rad/s from the closed form; z drift %.6e rad "
        "over %.0f s\n",
        earth == EarthShape::kWgs84Rotating ? "wgs84" : "sphere", worst_attitude, worst_rate, z_sum, cycles_s);
    EXPECT_LT(worst_attitude, 1e-15);
    EXPECT_LT(worst_rate, 1e-14);
    if (earth == EarthShape::kSphereNonRotating) {
      EXPECT_NEAR(z_sum, z_expected, 1e-14);
    }
  }
}

TEST(EmulatorScenarioTruth, RateTableHoldsItsConfiguredRates) {
  const ScenarioConfig scenario = scenario_test::shipped_scenario("rate_table.yaml", EarthShape::kWgs84Rotating);
  auto motion = make_motion_source(scenario);
  const auto& table = *scenario.rate_table;
  double t = 0.0, rate = 0.0, worst = 0.0;
  for (const auto& step : table.steps) {
    t += std::abs(step.rate_rad_s - rate) / table.acceleration_rad_s2;
    rate = step.rate_rad_s;
    const double middle = t + 0.5 * step.hold_s;
    const TruthState truth = motion->truth_at(middle);
    const Eigen::Vector3d earth_in_body =
        truth.attitude_body_to_enu.conjugate() * earth_rate_enu_rad_s(scenario.earth_model, scenario.latitude_rad);
    const Eigen::Vector3d axis_in_body = truth.attitude_body_to_enu.conjugate() * table.axis_enu;
    worst = std::max(worst, (truth.angular_rate_body_rad_s - earth_in_body - rate * axis_in_body).norm());
    t += step.hold_s;
  }
  std::printf("[rate table] worst |rate - Earth - configured| in the holds: %.1e rad/s\n", worst);
  EXPECT_LT(worst, 1e-15);
}

TEST(EmulatorScenarioTruth, TrajectoryFollowsItsLegs) {
  // Speed and yaw at each leg's end from the configured legs (plain sums in the test).
  const ScenarioConfig scenario = scenario_test::shipped_scenario("trajectory.yaml", EarthShape::kWgs84Rotating);
  auto motion = make_motion_source(scenario);
  double t = 0.0, speed = scenario.trajectory->initial_speed_m_s, yaw = scenario.trajectory->initial_yaw_rad;
  for (const auto& leg : scenario.trajectory->legs) {
    t += leg.duration_s;
    speed += leg.acceleration_m_s2 * leg.duration_s;
    yaw += leg.yaw_rate_rad_s * leg.duration_s;
    const TruthState truth = motion->truth_at(t);
    const Eigen::Vector3d expected = speed * Eigen::Vector3d(std::cos(yaw), std::sin(yaw), 0.0);
    EXPECT_LT((truth.velocity_enu_m_s - expected).norm(), 1e-12) << "leg ending at " << t;
    EXPECT_LT(truth.attitude_body_to_enu.angularDistance(attitude_from_roll_pitch_yaw(0.0, 0.0, yaw)), 1e-12);
  }
}

}  // namespace
}  // namespace emulator
}  // namespace imu_lab
