// The profile-level analytic AVAR (what bag_summary and the identification tests compare with)
// against emulated data from the shipped profiles, all six channels.
#include "imu_lab/emulator/analytic_profile_avar.h"

#include <gtest/gtest.h>

#include <cmath>

#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/noise/analytic_avar.h"
#include "test_emulator_paths.h"
#include "test_noise_avar_check.h"

namespace {

using imu_lab::emulator::analytic_axis_avar;

TEST(AnalyticProfileAvar, AntiAliasFilterMakesWhiteNoiseAMarkovProcess) {
  imu_lab::emulator::TriadErrorModel triad;
  triad.noise_per_axis[0].push_back(imu_lab::noise::WhiteRateParameters{1e-3});
  triad.bandwidth_hz = 20.0;
  const double correlation_time_s = 1.0 / (2.0 * M_PI * 20.0);
  for (double tau_s : {0.005, 0.05, 1.0}) {
    EXPECT_NEAR(analytic_axis_avar(triad, 0, tau_s, 0.005),
                imu_lab::noise::markov_avar(1e-3 / correlation_time_s, correlation_time_s, tau_s),
                1e-12 * imu_lab::noise::white_rate_avar(1e-3, tau_s));
  }
  // Far above the corner the filter no longer matters; near it, it pulls AVAR down.
  EXPECT_NEAR(analytic_axis_avar(triad, 0, 100.0, 0.005) / imu_lab::noise::white_rate_avar(1e-3, 100.0), 1.0, 1e-3);
  EXPECT_LT(analytic_axis_avar(triad, 0, 0.005, 0.005), 0.8 * imu_lab::noise::white_rate_avar(1e-3, 0.005));
}

// Every channel of two shipped profiles, emulated, against the profile's analytic curve
// (Bonferroni-corrected 99.7 % family-wise per channel).
TEST(AnalyticProfileAvar, ShippedProfilesAgreeWithTheirEmulatedData) {
  for (const char* profile_name : {"tactical_mems", "consumer_mems"}) {
    const auto profile =
        imu_lab::emulator::load_sensor_profile(imu_lab::test::config_path(std::string("sensors/") + profile_name + ".yaml"));
    const auto scenario = imu_lab::emulator::load_scenario(imu_lab::test::config_path("scenarios/static.yaml"));
    imu_lab::emulator::EmulatorSettings settings;
    settings.rate_hz = 200.0;
    settings.seed = 11;
    imu_lab::emulator::ImuEmulator emulator(profile, scenario, settings);
    const std::size_t count = 1 << 18;  // ~22 min of data
    std::array<std::vector<double>, 6> channels;
    for (std::size_t i = 0; i < count; ++i) {
      const auto sample = emulator.next();
      for (int axis = 0; axis < 3; ++axis) {
        channels[axis].push_back(sample.angular_rate_rad_s[axis]);
        channels[axis + 3].push_back(sample.specific_force_m_s2[axis]);
      }
    }
    const double tau0_s = 1.0 / settings.rate_hz;
    for (int c = 0; c < 6; ++c) {
      const auto& triad = c < 3 ? profile.gyro : profile.accelerometer;
      const auto check = imu_lab::test::check_avar(
          channels[c], tau0_s, [&](double tau_s) { return analytic_axis_avar(triad, c % 3, tau_s, tau0_s); }, 1,
          1 << 14);
      EXPECT_TRUE(check.passed()) << profile_name << " channel " << c << "\n" << check.table;
    }
  }
}

}  // namespace
