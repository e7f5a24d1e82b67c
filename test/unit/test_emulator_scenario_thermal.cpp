// Thermal scenarios: the sensor temperature lags the chamber as the first-order solution says
// (checked against the test's own RK4 of the lag equations), and the emulated bias and scale
// factor follow the profile's polynomial in temperature and its rate term within the noise.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>

#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/sensor_channel.h"
#include "test_emulator_scenario_support.h"

namespace imu_lab {
namespace emulator {
namespace {

// Chamber temperature rebuilt by the test from the configured segments.
double chamber_at(const ThermalConfig& thermal, double t) {
  double start = 0.0, value = thermal.initial_chamber_temperature_c;
  for (const auto& segment : thermal.segments) {
    if (t < start + segment.duration_s) return value + segment.rate_c_s * (t - start);
    value += segment.rate_c_s * segment.duration_s;
    start += segment.duration_s;
  }
  return value;
}

TEST(EmulatorScenarioThermal, SensorsLagTheChamberAsTheFirstOrderSolution) {
  const ScenarioConfig scenario = load_scenario(test::config_path("scenarios/thermal_chamber.yaml"));
  const ThermalConfig& thermal = *scenario.thermal;
  auto motion = make_motion_source(scenario);
  auto heating = [&](double t) {
    return thermal.p1_c * std::exp(thermal.p2_per_s * t) + thermal.p3_c * std::exp(thermal.p4_per_s * t) + thermal.p5_c;
  };
  const double tau1 = thermal.sensor_time_constant_s, tau2 = *thermal.second_sensor_time_constant_s;
  // State: lagged chamber x, second sensor y; tau1 x' = u - x, tau2 y' = x + F - y. RK4, 0.5 s
  // steps that land on every segment boundary (all are whole seconds).
  double x = thermal.initial_chamber_temperature_c, y = x + heating(0.0);
  auto derivative = [&](double t, double xs, double ys) {
    return std::pair{(chamber_at(thermal, t) - xs) / tau1, (xs + heating(t) - ys) / tau2};
  };
  const double h = 0.5;
  double worst_sensor = 0.0, worst_second = 0.0, worst_rate = 0.0;
  for (int k = 0; k < static_cast<int>(scenario.duration_s / h); ++k) {
    const double t = k * h;
    // Evaluate the chamber just inside the step so a ramp's kink at t is taken from the right.
    const double tin = t + 1e-9, tend = t + h - 1e-9;
    const auto k1 = derivative(tin, x, y);
    const auto k2 = derivative(t + h / 2, x + h / 2 * k1.first, y + h / 2 * k1.second);
    const auto k3 = derivative(t + h / 2, x + h / 2 * k2.first, y + h / 2 * k2.second);
    const auto k4 = derivative(tend, x + h * k3.first, y + h * k3.second);
    x += h / 6 * (k1.first + 2 * k2.first + 2 * k3.first + k4.first);
    y += h / 6 * (k1.second + 2 * k2.second + 2 * k3.second + k4.second);
    const TruthState truth = motion->truth_at(t + h);
    worst_sensor = std::max(worst_sensor, std::abs(truth.temperature_c - (x + heating(t + h))));
    worst_second = std::max(worst_second, std::abs(*truth.second_temperature_c - y));
    if (k % 97 == 0) {
      const double rate =
          (motion->truth_at(t + h + 1e-3).temperature_c - motion->truth_at(t + h - 1e-3).temperature_c) / 2e-3;
      worst_rate = std::max(worst_rate, std::abs(truth.temperature_rate_c_s - rate));
    }
  }
  // After the 40-minute ramp to -20 (4 tau), the sensor lags by rate * tau (1 - e^{-4}).
  const double ramp_end = 1800.0 + 2400.0;
  const TruthState at_ramp_end = motion->truth_at(ramp_end);
  const double lag = at_ramp_end.temperature_c - heating(ramp_end) - (-20.0);
  const double expected_lag = (1.0 / 60.0) * tau1 * (1.0 - std::exp(-2400.0 / tau1));
  std::printf(
      "[thermal] 6 h chamber run vs RK4: sensor %.1e degC, second sensor %.1e degC, rate %.1e degC/s; "
      "lag at the end of the ramp %.4f degC (first order: %.4f)\n",
      worst_sensor, worst_second, worst_rate, lag, expected_lag);
  EXPECT_LT(worst_sensor, 1e-8);
  EXPECT_LT(worst_second, 1e-8);
  EXPECT_LT(worst_rate, 1e-7);
  EXPECT_NEAR(lag, expected_lag, 1e-9);
}

// A white-noise-only profile with strong temperature terms, in a fast thermal scenario.
SensorProfile thermal_profile() {
  SensorProfile profile;
  profile.name = "thermal_white";
  for (int axis = 0; axis < 3; ++axis) {
    profile.gyro.noise_per_axis[axis] = {noise::WhiteRateParameters{1e-4}};
    profile.accelerometer.noise_per_axis[axis] = {noise::WhiteRateParameters{1e-3}};
  }
  ThermalSensitivity& gyro = profile.gyro.thermal;
  gyro.bias_polynomial = {Eigen::Vector3d(1e-5, -2e-5, 1.5e-5), Eigen::Vector3d(2e-7, 1e-7, -3e-7)};
  gyro.bias_per_temperature_rate = Eigen::Vector3d(3e-3, -2e-3, 1e-3);
  ThermalSensitivity& accel = profile.accelerometer.thermal;
  accel.bias_polynomial = {Eigen::Vector3d(1e-3, -5e-4, 8e-4)};
  accel.scale_factor_polynomial_ppm = {Eigen::Vector3d(50.0, 40.0, 60.0), Eigen::Vector3d::Constant(1.0)};
  accel.scale_factor_ppm_per_temperature_rate = Eigen::Vector3d::Constant(5000.0);
  return profile;
}

// Model value written out by the test: poly(dT) with rows k multiplying dT^(k+1).
Eigen::Vector3d polynomial(const std::vector<Eigen::Vector3d>& rows, double dt_c) {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < rows.size(); ++k) value += rows[k] * std::pow(dt_c, static_cast<double>(k + 1));
  return value;
}

TEST(EmulatorScenarioThermal, EmulatedBiasFollowsThePolynomialWithinTheNoise) {
  const char* const kScenario = R"(
type: static
latitude_deg: 45.0
longitude_deg: 10.0
height_m: 0.0
roll_deg: 0.0
pitch_deg: 0.0
yaw_deg: 0.0
earth_model: wgs84_rotating
duration_s: 1500.0
thermal:
  initial_chamber_temperature_c: 20.0
  sensor_time_constant_s: 60.0
  segments:
    - {soak_s: 60.0}
    - {ramp_to_c: -20.0, rate_c_per_min: 10.0}
    - {soak_s: 300.0}
    - {ramp_to_c: 60.0, rate_c_per_min: 10.0}
    - {soak_s: 300.0}
)";
  const ScenarioConfig scenario = scenario_from_yaml(YAML::Load(kScenario), "thermal_test.yaml");
  const SensorProfile profile = thermal_profile();
  const EmulatorSettings settings{100.0, 1.0e9, 11};
  ImuEmulator emulator(profile, scenario, settings);
  auto temperatures = make_motion_source(scenario);  // for T at the window edges
  const ThermalSensitivity& g = profile.gyro.thermal;
  const ThermalSensitivity& a = profile.accelerometer.thermal;
  const int window = 1000;  // 10 s; the white noise's standard error over it:
  const double window_s = window / settings.rate_hz;
  const Eigen::Vector3d sigma(1e-4 / std::sqrt(window_s), 1e-3 / std::sqrt(window_s), 0.0);
  double worst_z = 0.0, largest_thermal_z = 0.0;
  const int windows = static_cast<int>(scenario.duration_s / window_s);
  for (int w = 0; w < windows; ++w) {
    Eigen::Vector3d gyro_residual = Eigen::Vector3d::Zero(), accel_residual = Eigen::Vector3d::Zero();
    Eigen::Vector3d gyro_thermal = Eigen::Vector3d::Zero(), accel_thermal = Eigen::Vector3d::Zero();
    for (int k = 0; k < window; ++k) {
      const EmulatedSample s = emulator.next();
      const double dt_c = s.temperature_c - 20.0;                 // the interval's mean temperature
      const Eigen::Vector3d force = s.truth.specific_force_m_s2;  // static: constant
      const Eigen::Vector3d gyro_model = polynomial(g.bias_polynomial, dt_c);
      const Eigen::Vector3d accel_model = polynomial(a.bias_polynomial, dt_c) +
                                          1e-6 * polynomial(a.scale_factor_polynomial_ppm, dt_c).cwiseProduct(force);
      gyro_thermal += gyro_model / window;
      accel_thermal += accel_model / window;
      gyro_residual += (s.angular_rate_rad_s - s.truth.angular_rate_rad_s - gyro_model) / window;
      accel_residual += (s.specific_force_m_s2 - force - accel_model) / window;
    }
    // Rate terms: the window's mean rate of change is (T_end - T_start) / window, exactly.
    const double mean_rate = (temperatures->truth_at((w + 1) * window_s).temperature_c -
                              temperatures->truth_at(w * window_s).temperature_c) /
                             window_s;
    const Eigen::Vector3d force = temperatures->truth_at(0.0).specific_force_body_m_s2;
    gyro_residual -= g.bias_per_temperature_rate * mean_rate;
    accel_residual -= 1e-6 * a.scale_factor_ppm_per_temperature_rate.cwiseProduct(force) * mean_rate;
    gyro_thermal += g.bias_per_temperature_rate * mean_rate;
    worst_z = std::max(
        {worst_z, gyro_residual.cwiseAbs().maxCoeff() / sigma[0], accel_residual.cwiseAbs().maxCoeff() / sigma[1]});
    largest_thermal_z = std::max({largest_thermal_z, gyro_thermal.cwiseAbs().maxCoeff() / sigma[0],
                                  accel_thermal.cwiseAbs().maxCoeff() / sigma[1]});
  }
  std::printf(
      "[thermal] %d windows of 10 s x 6 channels: worst |residual| = %.2f standard errors; "
      "the thermal terms reach %.0f standard errors\n",
      windows, worst_z, largest_thermal_z);
  // 900 near-independent z-scores: 4.9 sigma keeps the family-wise false alarm below 0.1 %.
  EXPECT_LT(worst_z, 4.9);
  EXPECT_GT(largest_thermal_z, 50.0);  // so the check could see a wrong model
}

TEST(EmulatorScenarioThermal, SecondThermosensorOnlyWhenConfigured) {
  const SensorProfile profile = load_sensor_profile(test::config_path("sensors/tactical_mems.yaml"));
  ImuEmulator with(profile, load_scenario(test::config_path("scenarios/thermal_chamber.yaml")), {100.0, 0.0, 1});
  ImuEmulator without(profile, load_scenario(test::config_path("scenarios/static.yaml")), {100.0, 0.0, 1});
  const EmulatedSample a = with.next(), b = without.next();
  ASSERT_TRUE(a.second_temperature_c.has_value() && a.truth.second_temperature_c.has_value());
  EXPECT_NEAR(*a.second_temperature_c, 20.0, 1e-6);  // the chamber starts at 20, self-heating at 0
  EXPECT_FALSE(b.second_temperature_c.has_value() || b.truth.second_temperature_c.has_value());
}

}  // namespace
}  // namespace emulator
}  // namespace imu_lab
