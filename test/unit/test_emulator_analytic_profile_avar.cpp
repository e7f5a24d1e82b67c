// The profile-level analytic AVAR (what bag_summary and the identification tests compare with)
// against emulated data from the shipped profiles, all six channels.
#include "imu_lab/emulator/analytic_profile_avar.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdio>
#include <variant>

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

// The EDF of a channel's points. A sinusoid is left out of the power-law slope (near 1 / f its
// AVAR falls steeply and would pass for white phase noise; judging the whole AVAR at the
// stochastic part's EDF is conservative, test_noise_avar_check.h). A resonance is narrow-band:
// far fewer degrees of freedom than any power law (2 x width x record length), so its exact EDF
// (test::stationary_angle_edf) is taken, and the channel's EDF is the smaller of the two: for a
// sum of independent parts the estimator's standard deviation is at most the sum of the parts'
// (Cauchy-Schwarz on the quadratic form), so EDF >= the smallest part's EDF.
imu_lab::test::EdfOfFactor channel_edf(const std::vector<imu_lab::noise::ProcessParameters>& processes,
                                       const std::function<double(double)>& expected, double tau0_s, int max_factor) {
  std::vector<imu_lab::noise::SinusoidParameters> lines;
  std::vector<imu_lab::noise::ResonanceParameters> modes;
  for (const auto& parameters : processes) {
    if (const auto* line = std::get_if<imu_lab::noise::SinusoidParameters>(&parameters)) lines.push_back(*line);
    if (const auto* mode = std::get_if<imu_lab::noise::ResonanceParameters>(&parameters)) modes.push_back(*mode);
  }
  const auto rest = [=](double tau_s) {
    double avar = expected(tau_s);
    for (const auto& line : lines) avar -= imu_lab::noise::sinusoid_avar(line.amplitude, line.frequency_hz, tau_s);
    for (const auto& mode : modes) {
      avar -= imu_lab::noise::resonance_avar(mode.rms, mode.natural_frequency_hz, mode.width_hz, tau_s);
    }
    return avar;
  };
  std::vector<imu_lab::test::EdfOfFactor> parts{imu_lab::test::power_law_edf(rest, tau0_s)};
  for (const auto& mode : modes) {
    const double angle_variance = std::pow(mode.rms / (2.0 * M_PI * mode.natural_frequency_hz), 2);
    // The angle's correlation e^{-pi width u} is below 1e-16 after 12 / width seconds.
    const long correlation_samples = static_cast<long>(std::ceil(12.0 / (mode.width_hz * tau0_s)));
    parts.push_back(imu_lab::test::stationary_angle_edf(
        [=](double lag_s) {
          return angle_variance *
                 imu_lab::noise::resonance_angle_correlation(mode.natural_frequency_hz, mode.width_hz, lag_s);
        },
        tau0_s, correlation_samples, max_factor));
  }
  return [parts](int m, std::size_t count) {
    double edf = parts.front()(m, count);
    for (const auto& part : parts) edf = std::min(edf, part(m, count));
    return edf;
  };
}

// Every channel of the shipped profiles, emulated at their rates, against the profile's analytic
// curve (Bonferroni-corrected 99.7 % family-wise per channel, EDF from channel_edf).
// mems_front_end adds the low-passed white noise, the gyro-z resonance, the accelerometers'
// 0.56 Hz line and both LSBs.
TEST(AnalyticProfileAvar, ShippedProfilesAgreeWithTheirEmulatedData) {
  struct Shipped {
    const char* name;
    double rate_hz;
    int max_factor;
  };
  for (const Shipped shipped : {Shipped{"tactical_mems", 200.0, 1 << 14}, Shipped{"consumer_mems", 200.0, 1 << 14},
                                Shipped{"mems_front_end", 100.0, 1 << 13}}) {
    const auto profile = imu_lab::emulator::load_sensor_profile(
        imu_lab::test::config_path(std::string("sensors/") + shipped.name + ".yaml"));
    const auto scenario = imu_lab::emulator::load_scenario(imu_lab::test::config_path("scenarios/static.yaml"));
    imu_lab::emulator::EmulatorSettings settings;
    settings.rate_hz = shipped.rate_hz;
    settings.seed = 11;
    imu_lab::emulator::ImuEmulator emulator(profile, scenario, settings);
    const std::size_t count = 1 << 18;  // ~22 min of data at 200 Hz
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
      const auto expected = [&](double tau_s) { return analytic_axis_avar(triad, c % 3, tau_s, tau0_s); };
      const auto check =
          imu_lab::test::check_avar(channels[c], tau0_s, expected, 1, shipped.max_factor, 0.997,
                                    channel_edf(triad.noise_per_axis[c % 3], expected, tau0_s, shipped.max_factor));
      EXPECT_TRUE(check.passed()) << shipped.name << " channel " << c << "\n" << check.table;
      std::printf("[profile avar] %-14s channel %d: worst normalised deviation %.2f, rejected %d of %d\n", shipped.name,
                  c, check.worst_normalised_deviation, check.rejected_points, check.point_count);
    }
  }
}

}  // namespace
