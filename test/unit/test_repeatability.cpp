// Run-to-run repeatability: the spread's chi-squared interval covers the true sigma as often as
// its confidence says, and on emulated switch-ons (the emulator draws a turn-on bias per seed)
// the reported spread's interval holds the expected spread and each run's bias its emulated value.
#include "imu_lab/repeatability/repeatability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <variant>
#include <random>

#include "imu_lab/emulator/analytic_profile_avar.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/emulator/sensor_channel.h"
#include "test_emulator_paths.h"

namespace {

using imu_lab::repeatability::kChannelCount;
using imu_lab::repeatability::spread_of;

TEST(Repeatability, SpreadIsTheSampleDeviationWithNMinusOne) {
  const auto spread = spread_of({1.0, 2.0, 3.0, 4.0}, 0.95);
  EXPECT_EQ(spread.count, 4u);
  EXPECT_DOUBLE_EQ(spread.mean, 2.5);
  EXPECT_DOUBLE_EQ(spread.standard_deviation, std::sqrt(5.0 / 3.0));
  // chi-squared with 3 degrees of freedom: 2.5 % and 97.5 % quantiles 0.2158 and 9.348.
  EXPECT_NEAR(spread.lower, std::sqrt(5.0 / 9.348404), 1e-5);
  EXPECT_NEAR(spread.upper, std::sqrt(5.0 / 0.2157953), 1e-5);
  EXPECT_THROW(spread_of({1.0}, 0.95), std::invalid_argument);
  EXPECT_THROW(spread_of({1.0, NAN}, 0.95), std::invalid_argument);
}

// 4000 sets of 20 normal values: the 95 % interval holds the true sigma in 95 % of them
// (binomial standard error 0.34 %; the bound is 4 of them).
TEST(Repeatability, TheIntervalCoversTheTrueSigmaAsOftenAsItsConfidence) {
  std::mt19937_64 generator(18);
  std::normal_distribution<double> normal(3.0, 2.0);
  const int trials = 4000;
  int covered = 0;
  for (int t = 0; t < trials; ++t) {
    std::vector<double> values(20);
    for (double& value : values) value = normal(generator);
    const auto spread = spread_of(values, 0.95);
    covered += spread.lower <= 2.0 && 2.0 <= spread.upper ? 1 : 0;
  }
  EXPECT_NEAR(covered / static_cast<double>(trials), 0.95, 4 * std::sqrt(0.95 * 0.05 / trials));
}

// 24 emulated switch-ons of a tactical MEMS at rest, 120 s each at 100 Hz. The profile's scale
// factor, misalignment, g-sensitivity and thermal terms are taken out so that a run's emulated
// bias is its drawn total bias plus the (known) Earth rate and gravity. Its bias instability is
// taken out too: the emulator makes it with a stationary bank of Markov processes (corners down to
// 1/20000 s), whose slow states sit in a run's mean like a switch-on bias, so the variance of a
// run's mean is no longer AVAR(T) (doc/repeatability.md); white noise and the random walk from
// zero, which stay, have exactly that variance (IEEE Std 952 annex C).
TEST(Repeatability, EmulatedSwitchOnsGiveTheirTurnOnSpreadAndBiases) {
  auto profile = imu_lab::emulator::load_sensor_profile(imu_lab::test::config_path("sensors/tactical_mems.yaml"));
  for (auto* triad : {&profile.gyro, &profile.accelerometer}) {
    triad->scale_factor_error_ppm.setZero();
    triad->misalignment_rad.setZero();
    triad->g_sensitivity.setZero();
    triad->thermal = imu_lab::emulator::ThermalSensitivity();
    for (auto& processes : triad->noise_per_axis) {
      processes.erase(
          std::remove_if(processes.begin(), processes.end(),
                         [](const imu_lab::noise::ProcessParameters& process) {
                           return std::holds_alternative<imu_lab::noise::BiasInstabilityParameters>(process);
                         }),
          processes.end());
    }
  }
  const auto scenario = imu_lab::emulator::load_scenario(imu_lab::test::config_path("scenarios/static.yaml"));
  const double rate_hz = 100.0, tau0_s = 1.0 / rate_hz;
  const std::size_t count = 12000;
  const int run_count = 24;
  std::vector<imu_lab::repeatability::RunSummary> runs;
  std::vector<std::array<double, kChannelCount>> emulated(run_count);
  for (int run = 0; run < run_count; ++run) {
    imu_lab::emulator::ImuEmulator emulator(profile, scenario, {rate_hz, 0.0, 1000u + static_cast<unsigned>(run)});
    std::vector<std::array<double, kChannelCount>> samples(count);
    std::array<double, kChannelCount> truth_sum{};
    for (auto& row : samples) {
      const auto sample = emulator.next();
      for (int axis = 0; axis < 3; ++axis) {
        row[axis] = sample.angular_rate_rad_s[axis];
        row[axis + 3] = sample.specific_force_m_s2[axis];
        truth_sum[axis] += sample.truth.angular_rate_rad_s[axis];
        truth_sum[axis + 3] += sample.truth.specific_force_m_s2[axis];
      }
    }
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      const auto& channel = c < 3 ? emulator.gyro_channel() : emulator.accelerometer_channel();
      emulated[run][c] = channel.total_bias()[c % 3] + truth_sum[c] / count;
    }
    runs.push_back(imu_lab::repeatability::summarise_run("run" + std::to_string(run), samples, tau0_s));
  }
  const auto table = imu_lab::repeatability::repeatability_table(runs, 0.95);
  int inside = 0;
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    const auto& triad = c < 3 ? profile.gyro : profile.accelerometer;
    const double run_mean_variance = imu_lab::emulator::analytic_axis_avar(triad, c % 3, count * tau0_s, tau0_s);
    const double turn_on = triad.bias_turn_on_sigma[c % 3];
    const double expected = std::sqrt(turn_on * turn_on + run_mean_variance);
    const auto& spread = table.bias_spread[c];
    const bool holds = spread.lower <= expected && expected <= spread.upper;
    inside += holds ? 1 : 0;
    std::printf("%s: spread %.4g [%.4g, %.4g], expected %.4g (turn-on %.3g, run mean %.3g), rms uncertainty %.4g\n",
                imu_lab::repeatability::kChannelNames[c], spread.standard_deviation, spread.lower, spread.upper,
                expected, turn_on, std::sqrt(run_mean_variance), table.rms_mean_uncertainty[c]);
    // 24 x 6 values at 3 sigma: about 0.4 outside would be expected by chance; the fixed seeds give none.
    for (int run = 0; run < run_count; ++run) {
      const auto& r = table.runs[run].channels[c];
      EXPECT_LE(std::abs(r.bias - emulated[run][c]), 3.0 * r.mean_uncertainty)
          << imu_lab::repeatability::kChannelNames[c] << " run " << run;
    }
  }
  EXPECT_GE(inside, 5);
}

TEST(Repeatability, CalibrationParametersMustBeTheSameInEachCalibration) {
  using Calibration = std::vector<std::pair<std::string, double>>;
  const std::vector<Calibration> calibrations = {{{"gyro_sf_x", 1.0}, {"gyro_sf_y", 2.0}},
                                                 {{"gyro_sf_x", 3.0}, {"gyro_sf_y", 2.0}}};
  const auto spreads = imu_lab::repeatability::parameter_spreads(calibrations, "ppm", 0.95);
  ASSERT_EQ(spreads.size(), 2u);
  EXPECT_DOUBLE_EQ(spreads[0].spread.standard_deviation, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(spreads[1].spread.standard_deviation, 0.0);
  EXPECT_THROW(imu_lab::repeatability::parameter_spreads({calibrations[0], {{"gyro_sf_y", 1.0}, {"gyro_sf_x", 1.0}}},
                                                         "ppm", 0.95),
               std::invalid_argument);
}

}  // namespace
