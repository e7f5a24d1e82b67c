// The warm-up fit (thermal/warm_up_transient.h) on emulated truth: a static sensor in a
// constant-temperature room whose self-heating (config/scenarios/static_warm_up.yaml) drives the
// bias through linear thermal terms, so the output carries exactly two exponentials plus white,
// flicker and random-walk noise. The removed transient must equal the emulated one within 3 of
// its sigmas, and the Allan curve after removal must match the profile's analytic curve within
// its band where the curve before removal does not.
#include "imu_lab/thermal/warm_up_transient.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "imu_lab/emulator/analytic_profile_avar.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/emulator/thermal_profile.h"
#include "test_emulator_paths.h"
#include "test_noise_avar_check.h"

namespace {

using imu_lab::thermal::WarmUpBlockMeans;
using imu_lab::thermal::WarmUpFit;

constexpr double kRateHz = 10.0;
constexpr double kBlockS = 1.0;

// White, flicker and random-walk noise on every axis; the bias linear in the temperature and in
// its rate, so a sum of exponentials in the temperature is one in the output.
imu_lab::emulator::TriadErrorModel warming_triad(double white, double flicker, double random_walk, double per_degree,
                                                 double per_degree_per_s) {
  imu_lab::emulator::TriadErrorModel triad;
  for (auto& axis : triad.noise_per_axis) {
    axis.push_back(imu_lab::noise::WhiteRateParameters{white});
    axis.push_back(imu_lab::noise::BiasInstabilityParameters{flicker, 1.0, 1.0, 20000.0});
    axis.push_back(imu_lab::noise::RandomWalkParameters{random_walk});
  }
  triad.thermal.reference_temperature_c = 25.0;
  triad.thermal.bias_polynomial.push_back(Eigen::Vector3d::Constant(per_degree));
  triad.thermal.bias_per_temperature_rate = Eigen::Vector3d::Constant(per_degree_per_s);
  return triad;
}

imu_lab::emulator::SensorProfile warming_profile() {
  imu_lab::emulator::SensorProfile profile;
  profile.name = "warming";
  profile.gyro = warming_triad(5e-6, 2.5e-7, 1.25e-9, 2e-5, 5e-3);
  profile.accelerometer = warming_triad(5e-5, 2.5e-6, 1.25e-8, 2e-4, 5e-2);
  return profile;
}

struct EmulatedRun {
  std::array<std::vector<double>, 6> rates;  // every sample, per channel
  WarmUpBlockMeans blocks{6, kBlockS};
  double tau0_s = 1.0 / kRateHz;
};

EmulatedRun emulate(const std::string& scenario_file, std::uint64_t seed, double duration_s) {
  const auto scenario = imu_lab::emulator::load_scenario(imu_lab::test::config_path("scenarios/" + scenario_file));
  imu_lab::emulator::EmulatorSettings settings;
  settings.rate_hz = kRateHz;
  settings.seed = seed;
  imu_lab::emulator::ImuEmulator emulator(warming_profile(), scenario, settings);
  EmulatedRun run;
  const auto count = static_cast<std::size_t>(duration_s * kRateHz);
  for (std::size_t i = 0; i < count; ++i) {
    const auto sample = emulator.next();
    std::array<double, 6> values;
    for (int axis = 0; axis < 3; ++axis) {
      values[axis] = sample.angular_rate_rad_s[axis];
      values[axis + 3] = sample.specific_force_m_s2[axis];
    }
    for (int c = 0; c < 6; ++c) run.rates[c].push_back(values[c]);
    run.blocks.push(sample.stamp_ns, values.data());
  }
  return run;
}

// The emulated transient of a channel at time t from the first sample: the thermal bias at the
// sensor's temperature and rate minus its settled value. A sample is the interval's average and
// its stamp the interval's end, so time t of the fit is scenario time t + tau0 / 2.
double emulated_transient(int channel, double time_s) {
  const auto scenario = imu_lab::emulator::load_scenario(imu_lab::test::config_path("scenarios/static_warm_up.yaml"));
  const imu_lab::emulator::ThermalProfile temperatures(*scenario.thermal);
  const auto profile = warming_profile();
  const auto& thermal = channel < 3 ? profile.gyro.thermal : profile.accelerometer.thermal;
  const double scenario_s = time_s + 0.5 / kRateHz;
  const double settled_c = scenario.thermal->initial_chamber_temperature_c + scenario.thermal->p5_c;
  return thermal.bias(temperatures.sensor_temperature_c(scenario_s),
                      temperatures.sensor_temperature_rate_c_s(scenario_s))[channel % 3] -
         thermal.bias(settled_c, 0.0)[channel % 3];
}

constexpr std::array<double, 7> kCheckTimesS = {0.0, 300.0, 1000.0, 2000.0, 4000.0, 8000.0, 15000.0};

TEST(WarmUpTransient, EmulatedSelfHeatingIsFoundAndRemoved) {
  const EmulatedRun run = emulate("static_warm_up.yaml", 7, 21600.0);
  const auto profile = warming_profile();
  for (int c = 0; c < 6; ++c) {
    const WarmUpFit fit = imu_lab::thermal::fit_warm_up(run.blocks.blocks(c), kBlockS);
    ASSERT_FALSE(fit.terms.empty()) << "channel " << c;
    std::printf("[warm-up] channel %d: %zu exponentials, first T %.0f +- %.0f s, inflation %.2f\n", c, fit.terms.size(),
                fit.terms[0].time_constant_s, fit.terms[0].time_constant_sigma_s, fit.correlation_inflation);
    for (const double time_s : kCheckTimesS) {
      const double truth = emulated_transient(c, time_s);
      EXPECT_NEAR(fit.transient(time_s), truth, 3.0 * fit.transient_sigma(time_s))
          << "channel " << c << " at " << time_s << " s";
    }

    // The Allan curve against the profile's, before and after the removal.
    const auto& triad = c < 3 ? profile.gyro : profile.accelerometer;
    const auto expected = [&](double tau_s) {
      return imu_lab::emulator::analytic_axis_avar(triad, c % 3, tau_s, run.tau0_s);
    };
    std::vector<double> removed = run.rates[c];
    for (std::size_t i = 0; i < removed.size(); ++i) removed[i] -= fit.transient(static_cast<double>(i) * run.tau0_s);
    const auto before = imu_lab::test::check_avar(run.rates[c], run.tau0_s, expected, 1, 1 << 13);
    const auto after = imu_lab::test::check_avar(removed, run.tau0_s, expected, 1, 1 << 13);
    EXPECT_FALSE(before.passed()) << "channel " << c << ": the warm-up should show before its removal\n"
                                  << before.table;
    EXPECT_TRUE(after.passed()) << "channel " << c << "\n" << after.table;
  }
}

// Without a warm-up the F-test keeps no exponential: the noise's slow wander (flicker, random
// walk) is not taken for one.
TEST(WarmUpTransient, NoWarmUpNoTerm) {
  for (const std::uint64_t seed : {3u, 4u}) {
    const EmulatedRun run = emulate("static.yaml", seed, 21600.0);
    for (int c = 0; c < 6; ++c) {
      const WarmUpFit fit = imu_lab::thermal::fit_warm_up(run.blocks.blocks(c), kBlockS);
      EXPECT_TRUE(fit.terms.empty()) << "seed " << seed << " channel " << c << ": " << fit.terms.size() << " terms, p "
                                     << fit.added_term_p.front();
    }
  }
}

// Coverage of the transient's sigma over seeds: the share of |fit - truth| / sigma within 1 and 3.
TEST(WarmUpTransient, SigmasCoverTheEmulatedTransient) {
  int within_one = 0, within_three = 0, count = 0;
  for (std::uint64_t seed = 100; seed < 108; ++seed) {
    const EmulatedRun run = emulate("static_warm_up.yaml", seed, 21600.0);
    for (int c = 0; c < 6; ++c) {
      const WarmUpFit fit = imu_lab::thermal::fit_warm_up(run.blocks.blocks(c), kBlockS);
      for (const double time_s : {0.0, 1000.0, 4000.0}) {
        const double z = (fit.transient(time_s) - emulated_transient(c, time_s)) / fit.transient_sigma(time_s);
        within_one += std::abs(z) <= 1.0;
        within_three += std::abs(z) <= 3.0;
        ++count;
      }
    }
  }
  std::printf("[warm-up coverage] %d values: within 1 sigma %.1f %%, within 3 sigma %.1f %%\n", count,
              100.0 * within_one / count, 100.0 * within_three / count);
  EXPECT_GE(within_three, count - 3);
}

TEST(WarmUpTransient, RefusesTooFewBlocks) {
  std::vector<imu_lab::thermal::WarmUpBlock> blocks(8, {0.0, 0.0, 1.0, 1});
  EXPECT_THROW(imu_lab::thermal::fit_warm_up(blocks, 1.0), std::invalid_argument);
  EXPECT_THROW(WarmUpBlockMeans(6, 0.0), std::invalid_argument);
}

}  // namespace
