// Rate-table scale-factor test (rate_table/scale_factor_test.h) on the emulator, whose gyro z has
// a bias, a scale-factor error, asymmetry, quadratic and cubic nonlinearity and a dead zone, on
// the shipped rate_table_scale_factor scenario (z on the table axis, Up, at 50.45 deg N).
// Truth: the same estimator applied to the plateau means of the error-free-noise twin of each run
// (same profile without its noise processes) gives every statistic's exact value; that twin's
// polynomial fit must reproduce the profile's terms (so the inputs, the Earth rate included, are
// right); the noisy estimates must lie within 3 sigma of the exact values, and over 30 seeds
// their scatter must match the sigmas (chi-squared bounds at 99.9 %).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "imu_lab/common/config_error.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/rate_table/rate_table_report.h"
#include "imu_lab/rate_table/scale_factor_test.h"
#include "test_emulator_paths.h"

namespace imu_lab {
namespace rate_table {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kFullScaleOfProfile_rad_s = 300.0 * kDeg;
constexpr double kScaleFactorErrorPpm = 800.0;
constexpr double kAsymmetryPpm = 600.0;
constexpr double kQuadraticPpmFs = 200.0;  // at the profile's full scale, 300 deg/s
constexpr double kCubicPpmFs = -400.0;
constexpr double kDeadZone_rad_s = 1.5 * kDeg;
constexpr double kBias_rad_s = 0.02 * kDeg;
constexpr double kWhiteDensity = 0.01 * kDeg;  // rad/s/sqrt(Hz)

emulator::ScenarioConfig scale_factor_scenario() {
  return emulator::load_scenario(test::config_path("scenarios/rate_table_scale_factor.yaml"));
}

emulator::SensorProfile gyro_profile(bool with_noise) {
  emulator::SensorProfile profile = emulator::load_sensor_profile(test::config_path("sensors/ideal.yaml"));
  emulator::TriadErrorModel& gyro = profile.gyro;
  gyro.bias_fixed.z() = kBias_rad_s;
  gyro.scale_factor_error_ppm.z() = kScaleFactorErrorPpm;
  gyro.scale_factor_asymmetry_ppm.z() = kAsymmetryPpm;
  gyro.quadratic_nonlinearity_per_unit.z() = 1e-6 * kQuadraticPpmFs / kFullScaleOfProfile_rad_s;
  gyro.cubic_nonlinearity_per_unit2.z() = 1e-6 * kCubicPpmFs / (kFullScaleOfProfile_rad_s * kFullScaleOfProfile_rad_s);
  gyro.dead_zone.z() = kDeadZone_rad_s;
  if (with_noise) {
    for (auto& axis : gyro.noise_per_axis) axis = {noise::WhiteRateParameters{kWhiteDensity}};
  }
  return profile;
}

std::vector<io::ImuRecord> emulate(const emulator::SensorProfile& profile, std::uint64_t seed, double rate_hz) {
  const emulator::ScenarioConfig scenario = scale_factor_scenario();
  emulator::ImuEmulator emulator(profile, scenario, {rate_hz, 0.0, seed});
  std::vector<io::ImuRecord> samples;
  const auto count = static_cast<std::size_t>(scenario.duration_s * rate_hz);
  for (std::size_t k = 0; k < count; ++k) {
    samples.push_back(emulator::to_imu_record(emulator.next()));
  }
  return samples;
}

struct TableRun {
  ScaleFactorTestResult estimated;
  ScaleFactorTestResult exact;  // the estimator on the noise-free twin's plateau means
};

TableRun run_with_seed(std::uint64_t seed, double rate_hz = 100.0) {
  const RateTableSetup setup = setup_from_scenario(scale_factor_scenario());
  const ScaleFactorTestOptions options;
  TableRun run;
  run.estimated = run_scale_factor_test(emulate(gyro_profile(true), seed, rate_hz), setup, options);
  const std::vector<io::ImuRecord> clean = emulate(gyro_profile(false), seed, rate_hz);
  run.exact = run.estimated;
  for (PlateauMeasurement& m : run.exact.plateaus) {
    double sum = 0.0;
    for (std::size_t k = m.plateau.begin; k < m.plateau.end; ++k) sum += clean[k].angular_rate_rad_s.z();
    m.mean_output_rad_s = sum / static_cast<double>(m.plateau.size());
  }
  fit_plateau_measurements(run.exact, options);
  return run;
}

// Every reported estimate of a run, named, with its exact value.
struct Compared {
  std::string name;
  Estimate estimated;
  double exact;
};

std::vector<Compared> compared(const TableRun& run) {
  const ScaleFactorFit& l = run.estimated.line;
  const ScaleFactorFit& le = run.exact.line;
  std::vector<Compared> list = {
      {"line bias", l.bias_rad_s, le.bias_rad_s.value},
      {"line scale factor", l.scale_factor_error_ppm, le.scale_factor_error_ppm.value},
      {"line asymmetry", l.asymmetry_ppm, le.asymmetry_ppm.value},
      {"nonlinearity", run.estimated.nonlinearity_ppm_fs, run.exact.nonlinearity_ppm_fs.value}};
  if (run.estimated.polynomial && run.exact.polynomial) {
    const ScaleFactorFit& p = *run.estimated.polynomial;
    const ScaleFactorFit& pe = *run.exact.polynomial;
    list.push_back({"polynomial bias", p.bias_rad_s, pe.bias_rad_s.value});
    list.push_back({"polynomial scale factor", p.scale_factor_error_ppm, pe.scale_factor_error_ppm.value});
    list.push_back({"polynomial asymmetry", p.asymmetry_ppm, pe.asymmetry_ppm.value});
    list.push_back({"quadratic", p.quadratic_ppm_fs, pe.quadratic_ppm_fs.value});
    list.push_back({"cubic", p.cubic_ppm_fs, pe.cubic_ppm_fs.value});
  }
  return list;
}

TEST(RateTablePlateaus, EveryHoldOfTheScenarioIsFoundInsideIt) {
  const TableRun run = run_with_seed(1);
  const emulator::ScenarioConfig scenario = scale_factor_scenario();
  const auto& steps = scenario.rate_table->steps;
  ASSERT_EQ(run.estimated.plateaus.size(), steps.size());
  // Hold k runs from the end of its ramp to the start of the next one.
  double time_s = 0.0, rate = 0.0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    time_s += std::abs(steps[k].rate_rad_s - rate) / scenario.rate_table->acceleration_rad_s2;
    rate = steps[k].rate_rad_s;
    const Plateau& plateau = run.estimated.plateaus[k].plateau;
    const double end_s = plateau.start_s + plateau.duration_s;
    EXPECT_GE(plateau.start_s, time_s) << "hold " << k;
    // The table keeps the last rate to the end of the recording.
    const bool last = k + 1 == steps.size();
    if (!last) EXPECT_LE(end_s, time_s + steps[k].hold_s + 0.011) << "hold " << k;  // + one sample (stamp = end)
    // Lost at each end at most the window holding the rate change, the first window after it
    // (unsteady: its neighbour differs) and the 1 s guard.
    if (!last) EXPECT_GE(plateau.duration_s, steps[k].hold_s - 2.0 * 3.0 - 0.02) << "hold " << k;
    EXPECT_EQ(run.estimated.plateaus[k].nominal_rate_rad_s, steps[k].rate_rad_s);
    time_s += steps[k].hold_s;
  }
}

TEST(RateTableScaleFactor, NoiseFreeTwinReproducesTheProfileTerms) {
  const TableRun run = run_with_seed(1);
  ASSERT_TRUE(run.exact.polynomial.has_value());
  const ScaleFactorFit& p = *run.exact.polynomial;
  const double full_scale = run.exact.full_scale_rad_s;  // 300 deg/s + the Earth rate on Up
  EXPECT_NEAR(full_scale, 300.0 * kDeg + 7.292115e-5 * std::sin(50.45 * kDeg), 1e-12);
  EXPECT_NEAR(p.bias_rad_s.value, kBias_rad_s, 1e-12);
  EXPECT_NEAR(p.scale_factor_error_ppm.value, kScaleFactorErrorPpm, 1e-5);
  // (K+ - K-) / K with K+ - K- = 1e-6 A.
  EXPECT_NEAR(p.asymmetry_ppm.value, kAsymmetryPpm / (1.0 + 1e-6 * kScaleFactorErrorPpm), 1e-5);
  EXPECT_NEAR(p.quadratic_ppm_fs.value, kQuadraticPpmFs * full_scale / kFullScaleOfProfile_rad_s, 1e-5);
  EXPECT_NEAR(p.cubic_ppm_fs.value, kCubicPpmFs * std::pow(full_scale / kFullScaleOfProfile_rad_s, 2), 1e-5);
  // The dead zone (1.5 deg/s) lies between the dead 1 deg/s and the live 2 deg/s plateaus; the
  // rests are inside it too.
  ASSERT_TRUE(run.exact.dead_zone_found);
  EXPECT_NEAR(run.exact.dead_zone_above_rad_s, 1.0 * kDeg, 1e-4);
  ASSERT_TRUE(run.exact.dead_zone_below_rad_s.has_value());
  EXPECT_NEAR(*run.exact.dead_zone_below_rad_s, 2.0 * kDeg, 1e-4);
  int dead = 0;
  for (const auto& m : run.exact.plateaus) dead += m.dead;
  EXPECT_EQ(dead, 4);  // +-1 deg/s and the two rests
}

TEST(RateTableScaleFactor, EstimatesLieWithinThreeSigmaOfTheExactValues) {
  const TableRun run = run_with_seed(1);
  ASSERT_TRUE(run.estimated.polynomial.has_value());
  EXPECT_TRUE(run.estimated.dead_zone_found);
  EXPECT_EQ(run.estimated.dead_zone_above_rad_s, run.exact.dead_zone_above_rad_s);
  for (const Compared& c : compared(run)) {
    std::printf("  %-24s %14.6g +- %10.3g   exact %14.6g   z %+.2f\n", c.name.c_str(), c.estimated.value,
                c.estimated.sigma, c.exact, (c.estimated.value - c.exact) / c.estimated.sigma);
    EXPECT_GT(c.estimated.sigma, 0.0) << c.name;
    EXPECT_NEAR(c.estimated.value, c.exact, 3.0 * c.estimated.sigma) << c.name;
  }
  // The polynomial against the emulator's own terms (the inputs, Earth rate included, checked
  // through the estimates rather than the noise-free twin).
  const ScaleFactorFit& fit = *run.estimated.polynomial;
  const double full_scale = run.estimated.full_scale_rad_s;
  EXPECT_NEAR(fit.bias_rad_s.value, kBias_rad_s, 3.0 * fit.bias_rad_s.sigma);
  EXPECT_NEAR(fit.scale_factor_error_ppm.value, kScaleFactorErrorPpm, 3.0 * fit.scale_factor_error_ppm.sigma);
  EXPECT_NEAR(fit.asymmetry_ppm.value, kAsymmetryPpm / (1.0 + 1e-6 * kScaleFactorErrorPpm),
              3.0 * fit.asymmetry_ppm.sigma);
  EXPECT_NEAR(fit.quadratic_ppm_fs.value, kQuadraticPpmFs * full_scale / kFullScaleOfProfile_rad_s,
              3.0 * fit.quadratic_ppm_fs.sigma);
  EXPECT_NEAR(fit.cubic_ppm_fs.value, kCubicPpmFs * std::pow(full_scale / kFullScaleOfProfile_rad_s, 2),
              3.0 * fit.cubic_ppm_fs.sigma);
  // The straight lines leave the nonlinearity in their residuals: far above the noise here.
  EXPECT_GT(run.exact.nonlinearity_ppm_fs.value, 20.0 * run.estimated.nonlinearity_ppm_fs.sigma);
  // The polynomial is the emulator's model: its chi-squared is the noise's.
  EXPECT_LT(fit.chi_squared, 3.0 * fit.degrees_of_freedom + 10.0);
}

TEST(RateTableScaleFactor, SigmasMatchTheScatterOverSeeds) {
  constexpr int kSeeds = 30;
  std::vector<std::vector<double>> z;  // per estimate, (estimated - exact) / sigma over seeds
  std::vector<std::string> names;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const TableRun run = run_with_seed(100 + seed, 50.0);
    const std::vector<Compared> list = compared(run);
    if (z.empty()) {
      z.resize(list.size());
      for (const Compared& c : list) names.push_back(c.name);
    }
    ASSERT_EQ(list.size(), z.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
      z[i].push_back((list[i].estimated.value - list[i].exact) / list[i].estimated.sigma);
    }
  }
  // sqrt(chi2_30 / 30) at 0.05 % and 99.95 %.
  for (std::size_t i = 0; i < z.size(); ++i) {
    double squares = 0.0;
    for (double value : z[i]) squares += value * value;
    const double rms = std::sqrt(squares / kSeeds);
    std::printf("  %-24s rms z over %d seeds %.3f\n", names[i].c_str(), kSeeds, rms);
    EXPECT_GT(rms, 0.600) << names[i];
    EXPECT_LT(rms, 1.439) << names[i];
  }
}

// ---- Bad input ----

std::string write_table(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

std::string config_error_key(const std::function<void()>& action) {
  try {
    action();
  } catch (const ConfigError& error) {
    return error.key();
  }
  return "(no error)";
}

std::string input_error(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(RateTableBadInput, TableFilesAreRefusedNamingTheKey) {
  const std::string good = "latitude_deg: 50.45\naxis_enu: [0, 0, 1]\nyaw_deg: 90\nrates_deg_s: [0, 1, -1, 10, -10]\n";
  const RateTableSetup setup = load_rate_table_setup(write_table("rt_good.yaml", good));
  EXPECT_EQ(setup.tested_axis(), 2);
  EXPECT_EQ(setup.nominal_rates_rad_s.size(), 5u);
  EXPECT_EQ(config_error_key([] {
              load_rate_table_setup(write_table("rt_a.yaml", "latitude_deg: 50\nrates_deg_s: [1, -1, 2]\nrate: 3\n"));
            }),
            "rate");
  EXPECT_EQ(config_error_key(
                [] { load_rate_table_setup(write_table("rt_b.yaml", "latitude_deg: 95\nrates_deg_s: [1, -1, 2]\n")); }),
            "latitude_deg");
  EXPECT_EQ(config_error_key(
                [] { load_rate_table_setup(write_table("rt_c.yaml", "latitude_deg: 50\nrates_deg_s: [1, x, 2]\n")); }),
            "rates_deg_s[1]");
  EXPECT_EQ(config_error_key(
                [] { load_rate_table_setup(write_table("rt_d.yaml", "latitude_deg: 50\nrates_deg_s: [1, -1]\n")); }),
            "rates_deg_s");
  // Table axis North with body x North only at yaw 90... here yaw 45: no axis on the table axis.
  EXPECT_EQ(config_error_key([] {
              load_rate_table_setup(write_table(
                  "rt_e.yaml", "latitude_deg: 50\naxis_enu: [0, 1, 0]\nyaw_deg: 45\nrates_deg_s: [1, -1, 2]\n"));
            }),
            "roll_deg/pitch_deg/yaw_deg");
  emulator::ScenarioConfig static_scenario = emulator::load_scenario(test::config_path("scenarios/static.yaml"));
  EXPECT_EQ(config_error_key([&] { setup_from_scenario(static_scenario); }), "type");
}

TEST(RateTableBadInput, PlateausThatDoNotFollowTheRatesAreRefusedListingThem) {
  const std::vector<io::ImuRecord> samples = emulate(gyro_profile(true), 7, 50.0);
  RateTableSetup setup = setup_from_scenario(scale_factor_scenario());
  RateTableSetup missing = setup;
  missing.nominal_rates_rad_s.pop_back();
  const std::string count = input_error([&] { run_scale_factor_test(samples, missing, {}); });
  EXPECT_NE(count.find("18 plateau levels found"), std::string::npos) << count;
  EXPECT_NE(count.find(" deg/s at "), std::string::npos) << count;  // the levels found, listed
  RateTableSetup swapped = setup;
  std::swap(swapped.nominal_rates_rad_s[13], swapped.nominal_rates_rad_s[15]);  // 200 and 300
  const std::string order = input_error([&] { run_scale_factor_test(samples, swapped, {}); });
  EXPECT_NE(order.find("do not follow the nominal rates"), std::string::npos) << order;
  // Too short for the plateaus.
  const std::vector<io::ImuRecord> head(samples.begin(), samples.begin() + 100);
  EXPECT_NE(input_error([&] { run_scale_factor_test(head, setup, {}); }).find("plateau"), std::string::npos);
}

TEST(RateTableReport, FilesCarryTheEstimatesAndOneRowPerPlateau) {
  const TableRun run = run_with_seed(1, 50.0);
  const std::string yaml = scale_factor_yaml(run.estimated, "run.bag");
  EXPECT_NE(yaml.find("scale_factor_error_ppm"), std::string::npos);
  EXPECT_NE(yaml.find("gyro_axis: z"), std::string::npos);
  const std::string csv = plateau_csv(run.estimated);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + static_cast<long>(run.estimated.plateaus.size()));
}

}  // namespace
}  // namespace rate_table
}  // namespace imu_lab
