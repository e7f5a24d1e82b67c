// The truth means what imu_lab/ImuTruth says: its angular rate and specific force are the
// interval averages the sensor measured, so the error-free profile (config/sensors/ideal.yaml)
// reads them exactly on any motion. Required: raw minus truth at most 1e-12 of the channel's
// largest |truth| over the whole scenario at 200 Hz. (Its output is 0 + I * input + 0, so the
// difference is round-off at most; a truth taken at the stamp instead of over the interval is
// off by up to 5e-2 rad/s at the trajectory's yaw-rate steps and ~3e-3 rad/s in coning at 400 Hz,
// i.e. of the order of the channel's own values.)
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/emulator/sensor_profile.h"
#include "test_emulator_paths.h"

namespace imu_lab {
namespace emulator {
namespace {

constexpr double kRateHz = 200.0;
constexpr double kRelativeBound = 1e-12;
const char* const kChannels[6] = {"gyro x", "gyro y", "gyro z", "accel x", "accel y", "accel z"};

TEST(EmulatorIdealProfile, EveryErrorTermIsZero) {
  const SensorProfile profile = load_sensor_profile(test::config_path("sensors/ideal.yaml"));
  for (const TriadErrorModel* triad : {&profile.gyro, &profile.accelerometer}) {
    EXPECT_TRUE(triad->bias_fixed.isZero(0.0));
    EXPECT_TRUE(triad->bias_turn_on_sigma.isZero(0.0));
    EXPECT_TRUE(triad->scale_misalignment_matrix().isIdentity(0.0));
    EXPECT_TRUE(triad->quadratic_nonlinearity_per_unit.isZero(0.0));
    EXPECT_TRUE(triad->g_sensitivity.isZero(0.0));
    EXPECT_EQ(triad->pulse_weight, 0.0);
    EXPECT_EQ(triad->bandwidth_hz, 0.0);
    EXPECT_TRUE(triad->thermal.bias_polynomial.empty() && triad->thermal.scale_factor_polynomial_ppm.empty());
    for (const auto& processes : triad->noise_per_axis) EXPECT_TRUE(processes.empty());
  }
}

class EmulatorIdealTruth : public ::testing::TestWithParam<const char*> {};

TEST_P(EmulatorIdealTruth, RawEqualsTheTruthsIntervalAverages) {
  const ScenarioConfig scenario = load_scenario(test::config_path(std::string("scenarios/") + GetParam()));
  EmulatorSettings settings;
  settings.rate_hz = kRateHz;
  ImuEmulator emulator(load_sensor_profile(test::config_path("sensors/ideal.yaml")), scenario, settings);
  const long samples = std::lround(scenario.duration_s * kRateHz);
  std::array<double, 6> largest_truth{}, largest_difference{}, largest_increment_difference{};
  for (long k = 0; k < samples; ++k) {
    const EmulatedSample s = emulator.next();
    Eigen::Matrix<double, 6, 1> truth, raw, increment;
    truth << s.truth.angular_rate_rad_s, s.truth.specific_force_m_s2;
    raw << s.angular_rate_rad_s, s.specific_force_m_s2;
    increment << s.delta_angle_rad, s.delta_velocity_m_s;
    for (int c = 0; c < 6; ++c) {
      largest_truth[c] = std::max(largest_truth[c], std::abs(truth[c]));
      largest_difference[c] = std::max(largest_difference[c], std::abs(raw[c] - truth[c]));
      largest_increment_difference[c] =
          std::max(largest_increment_difference[c], std::abs(increment[c] - truth[c] * emulator.sample_interval_s()));
    }
  }
  for (int c = 0; c < 6; ++c) {
    std::printf("[ideal] %s %s: largest |truth| %.3e, largest |raw - truth| %.3e\n", GetParam(), kChannels[c],
                largest_truth[c], largest_difference[c]);
    EXPECT_LE(largest_difference[c], kRelativeBound * largest_truth[c]) << kChannels[c];
    EXPECT_LE(largest_increment_difference[c], kRelativeBound * largest_truth[c] * emulator.sample_interval_s())
        << kChannels[c];
  }
}

INSTANTIATE_TEST_SUITE_P(MovingScenarios, EmulatorIdealTruth,
                         ::testing::Values("coning.yaml", "sculling.yaml", "rate_table.yaml", "trajectory.yaml"));

}  // namespace
}  // namespace emulator
}  // namespace imu_lab
