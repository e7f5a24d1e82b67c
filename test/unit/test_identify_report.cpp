// Outputs: the YAML report's numbers round-trip; kalibr_imu.yaml has Kalibr's keys and the
// continuous/discrete conversions; the partial-curve CSV carries each term's curve.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "identify_test_records.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/identify/fit_warnings.h"
#include "imu_lab/identify/kalibr_yaml.h"
#include "imu_lab/identify/noise_report.h"
#include "imu_lab/identify/profile_likelihood.h"
#include "imu_lab/identify/partial_curves.h"
#include "imu_lab/identify/triad_fit.h"
#include "imu_lab/identify/white_equivalent.h"

namespace imu_lab {
namespace identify {
namespace {

TriadFit exact_triad(SensorKind sensor, double n, double k) {
  std::array<std::vector<allan::StabilityPoint>, 3> curves;
  for (int axis = 0; axis < 3; ++axis) {
    NoiseModel model;
    model.terms = {{TermKind::kWhiteRate, n * (1.0 + 0.5 * axis), 0.0}, {TermKind::kRandomWalk, k, 0.0}};
    curves[axis] = identify_test::exact_octave_curve(model, 0.01, 7200.0);
  }
  return fit_triad(sensor, curves, 0.01, 7200.0);
}

// noise.yaml's band warnings: a range says on which side of the band the total lies, so where the
// total crosses the band between neighbouring taus the two sides are two ranges.
TEST(IdentifyBandExcursions, NeighboursOnOppositeSidesAreTwoRangesEachNamedByItsSide) {
  const auto point = [](double tau_s, double fitted) {
    BandPoint band_point;
    band_point.tau_s = tau_s;
    band_point.measured_deviation = 1.0;
    band_point.fitted_deviation = fitted;
    band_point.lower = 0.99;
    band_point.upper = 1.01;
    return band_point;
  };
  // above, above, below, below (a crossing between 0.02 and 0.03 s), inside, below
  const std::vector<BandPoint> band = {point(0.01, 1.03), point(0.02, 1.02), point(0.03, 0.95),
                                       point(0.04, 0.98), point(0.05, 1.0),  point(0.06, 0.97)};
  const std::vector<BandExcursion> runs = band_excursions(band);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_DOUBLE_EQ(runs[0].first_tau_s, 0.01);
  EXPECT_DOUBLE_EQ(runs[0].last_tau_s, 0.02);
  EXPECT_EQ(runs[0].point_count, 2);
  EXPECT_NEAR(runs[0].largest_excursion, 0.02, 1e-12);
  EXPECT_DOUBLE_EQ(runs[1].first_tau_s, 0.03);
  EXPECT_DOUBLE_EQ(runs[1].last_tau_s, 0.04);
  EXPECT_NEAR(runs[1].largest_excursion, -0.04, 1e-12);
  EXPECT_DOUBLE_EQ(runs[2].first_tau_s, 0.06);
  EXPECT_NEAR(runs[2].largest_excursion, -0.02, 1e-12);
}

TEST(IdentifyReport, NumbersRoundTripThroughTheYaml) {
  const std::vector<TriadFit> triads = {exact_triad(SensorKind::kGyroscope, 1e-4, 1e-6),
                                        exact_triad(SensorKind::kAccelerometer, 1e-3, 1e-5)};
  EXPECT_EQ(triads[0].worst_axis, 2);  // axis z has the largest N
  const auto values = read_noise_report_values(format_noise_report(triads, {"test", 100.0}));
  for (const TriadFit& triad : triads) {
    for (int axis = 0; axis < 3; ++axis) {
      const FitResult& fit = triad.axes[axis];
      const std::string base =
          "triads." + sensor_prefix(triad.sensor) + ".axes." + axis_name(triad.sensor, axis) + ".terms.";
      for (const TermEstimate& term : fit.terms) {
        for (const UnitScale& unit : amplitude_units(triad.sensor, term.kind)) {
          const std::string key = base + term.name + "." + parameter_key(amplitude_symbol(term.kind), unit.key);
          if (term.status == TermStatus::kAbsent) {
            EXPECT_EQ(values.count(key), 0u) << key << " must not carry a value";
            const std::string bound_key = key + upper_bound_suffix(0.95);
            ASSERT_EQ(values.count(bound_key), 1u) << bound_key;
            EXPECT_DOUBLE_EQ(values.at(bound_key), term.amplitude.upper_bound * unit.per_si);
            const std::string one_sigma_key = key + upper_bound_suffix(kOneSigmaConfidence);
            ASSERT_EQ(values.count(one_sigma_key), 1u) << one_sigma_key;
            EXPECT_DOUBLE_EQ(values.at(one_sigma_key), term.amplitude.upper_bound_one_sigma * unit.per_si);
            continue;
          }
          ASSERT_EQ(values.count(key), 1u) << key;
          EXPECT_DOUBLE_EQ(values.at(key), term.amplitude.value * unit.per_si) << key;
          EXPECT_DOUBLE_EQ(values.at(key + "_sigma"), term.amplitude.sigma * unit.per_si) << key;
        }
      }
      EXPECT_DOUBLE_EQ(values.at("triads." + sensor_prefix(triad.sensor) + ".axes." + axis_name(triad.sensor, axis) +
                                 ".fit_quality.p_value"),
                       fit.quality.p_value);
    }
  }
  // The fit of an exact curve is exact up to the second order of the moments' log-bias
  // correction (about 1 / EDF^2: 1e-5 relative here).
  EXPECT_NEAR(values.at("triads.gyro.axes.gyro_x.terms.white_rate.N_rad_s_per_sqrt_hz"), 1e-4, 1e-9);
  EXPECT_NEAR(values.at("triads.gyro.axes.gyro_x.terms.white_rate.N_deg_per_sqrt_h"),
              1e-4 * 180.0 / 3.14159265358979323846 * 60.0, 1e-5 * 0.344);
  // No Markov term here, so the white-equivalent density is N itself.
  EXPECT_DOUBLE_EQ(values.at("triads.gyro.axes.gyro_y.white_equivalent.N_rad_s_per_sqrt_hz"),
                   values.at("triads.gyro.axes.gyro_y.terms.white_rate.N_rad_s_per_sqrt_hz"));
  EXPECT_THROW(read_noise_report_values("a: 1"), InputError);
}

// What the attitude error budget reads back: each axis's present terms with their SI values and
// tau0; absent terms left out; a missing value named by its dotted key.
TEST(IdentifyReport, AxisModelsReadBackThePresentTerms) {
  const TriadFit triad = exact_triad(SensorKind::kGyroscope, 1e-4, 1e-6);
  const std::string text = format_noise_report({triad}, {"test", 100.0});
  const auto axes = read_reported_axis_models(text, SensorKind::kGyroscope);
  ASSERT_EQ(axes.size(), 3u);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(axes[axis].axis, axis_name(SensorKind::kGyroscope, axis));
    EXPECT_DOUBLE_EQ(axes[axis].tau0_s, triad.axes[axis].tau0_s);
    std::vector<Term> present;
    for (const TermEstimate& term : triad.axes[axis].terms) {
      if (term.status == TermStatus::kPresent) present.push_back({term.kind, term.amplitude.value, 0.0});
    }
    ASSERT_EQ(axes[axis].model.terms.size(), present.size()) << axis;
    for (const Term& expected : present) {
      const auto found = std::find_if(axes[axis].model.terms.begin(), axes[axis].model.terms.end(),
                                      [&](const Term& term) { return term.kind == expected.kind; });
      ASSERT_NE(found, axes[axis].model.terms.end()) << term_kind_name(expected.kind);
      EXPECT_NEAR(found->amplitude, expected.amplitude, 1e-15 * expected.amplitude);
    }
  }
  EXPECT_THROW(read_reported_axis_models(text, SensorKind::kAccelerometer), InputError);
  std::string cut = text;
  const std::size_t at = cut.find("N_rad_s_per_sqrt_hz:");
  ASSERT_NE(at, std::string::npos);
  cut.replace(at, 1, "X");
  try {
    read_reported_axis_models(cut, SensorKind::kGyroscope);
    ADD_FAILURE() << "a report without gyro_x's N was read";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("triads.gyro.axes.gyro_x.terms.white_rate.N_rad_s_per_sqrt_hz"),
              std::string::npos)
        << error.what();
  }
}

TEST(IdentifyReport, WrittenAtomicallyToAFile) {
  const std::vector<TriadFit> triads = {exact_triad(SensorKind::kGyroscope, 1e-4, 1e-6)};
  const std::string path = testing::TempDir() + "identify_report_test.yaml";
  write_noise_report(path, triads, {"test", 100.0});
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), format_noise_report(triads, {"test", 100.0}));
  std::remove(path.c_str());
}

// A triad fit made by hand: per axis, N present and K either present or absent with a bound.
TriadFit hand_triad(SensorKind sensor, const std::array<double, 3>& n, const std::array<double, 3>& k, bool k_present) {
  TriadFit triad;
  triad.sensor = sensor;
  for (int axis = 0; axis < 3; ++axis) {
    TermEstimate white;
    white.name = "white_rate";
    white.kind = TermKind::kWhiteRate;
    white.status = TermStatus::kPresent;
    white.amplitude.value = n[axis];
    TermEstimate walk;
    walk.name = "random_walk";
    walk.kind = TermKind::kRandomWalk;
    walk.status = k_present ? TermStatus::kPresent : TermStatus::kAbsent;
    (k_present ? walk.amplitude.value : walk.amplitude.upper_bound) = k[axis];
    triad.axes[axis].terms = {white, walk};
  }
  return triad;
}

TEST(IdentifyKalibr, KeysAndConversionsForAKnownModel) {
  const TriadFit gyro = hand_triad(SensorKind::kGyroscope, {1e-4, 3e-4, 2e-4}, {1e-6, 4e-6, 2e-6}, false);
  const TriadFit accel = hand_triad(SensorKind::kAccelerometer, {2e-3, 1e-3, 1.5e-3}, {3e-5, 1e-5, 2e-5}, true);
  const double rate_hz = 400.0;
  const KalibrImuNoise noise = kalibr_noise(gyro, accel, rate_hz, "/imu/raw");
  const YAML::Node yaml = YAML::Load(format_kalibr_imu_yaml(noise));
  EXPECT_DOUBLE_EQ(yaml["gyroscope_noise_density"].as<double>(), 3e-4);
  EXPECT_DOUBLE_EQ(yaml["gyroscope_random_walk"].as<double>(), 4e-6);
  EXPECT_DOUBLE_EQ(yaml["accelerometer_noise_density"].as<double>(), 2e-3);
  EXPECT_DOUBLE_EQ(yaml["accelerometer_random_walk"].as<double>(), 3e-5);
  EXPECT_DOUBLE_EQ(yaml["gyroscope_noise_density_discrete"].as<double>(), 3e-4 * 20.0);
  EXPECT_DOUBLE_EQ(yaml["gyroscope_random_walk_discrete"].as<double>(), 4e-6 / 20.0);
  EXPECT_DOUBLE_EQ(yaml["accelerometer_noise_density_discrete"].as<double>(), 2e-3 * 20.0);
  EXPECT_DOUBLE_EQ(yaml["accelerometer_random_walk_discrete"].as<double>(), 3e-5 / 20.0);
  EXPECT_TRUE(yaml["gyroscope_random_walk_is_upper_bound"].as<bool>());
  EXPECT_FALSE(yaml["gyroscope_noise_density_is_upper_bound"].as<bool>());
  EXPECT_FALSE(yaml["accelerometer_random_walk_is_upper_bound"].as<bool>());
  EXPECT_EQ(yaml["rostopic"].as<std::string>(), "/imu/raw");
  EXPECT_DOUBLE_EQ(yaml["update_rate"].as<double>(), 400.0);
  EXPECT_EQ(noise.gyroscope_noise_density.axis, 1);
}

// OpenVINS reads the four numbers key by key under imu0 (its config/*/kalibr_imu_chain.yaml), and
// its parser wants the IMU model and intrinsics there too; both files say to set the topic.
TEST(IdentifyKalibr, TheOpenVinsFileHoldsKalibrsNumbersUnderImu0) {
  const TriadFit gyro = hand_triad(SensorKind::kGyroscope, {1e-4, 3e-4, 2e-4}, {1e-6, 4e-6, 2e-6}, false);
  const TriadFit accel = hand_triad(SensorKind::kAccelerometer, {2e-3, 1e-3, 1.5e-3}, {3e-5, 1e-5, 2e-5}, true);
  const KalibrImuNoise noise = kalibr_noise(gyro, accel, 400.0, "/imu/raw");
  const std::string text = format_kalibr_imu_chain_yaml(noise);
  // OpenCV's FileStorage header; yaml-cpp reads the rest.
  ASSERT_EQ(text.rfind("%YAML:1.0\n", 0), 0u) << text;
  const YAML::Node chain = YAML::Load(text.substr(text.find('\n') + 1));
  const YAML::Node kalibr = YAML::Load(format_kalibr_imu_yaml(noise));
  ASSERT_TRUE(chain["imu0"].IsMap()) << text;
  for (const char* key : {"accelerometer_noise_density", "accelerometer_random_walk", "gyroscope_noise_density",
                          "gyroscope_random_walk", "update_rate"}) {
    EXPECT_DOUBLE_EQ(chain["imu0"][key].as<double>(), kalibr[key].as<double>()) << key;
  }
  EXPECT_EQ(chain["imu0"]["rostopic"].as<std::string>(), "/imu/raw");
  EXPECT_EQ(chain["imu0"]["model"].as<std::string>(), "kalibr");
  for (const char* matrix : {"Tw", "R_IMUtoGYRO", "Ta", "R_IMUtoACC"}) {
    const auto rows = chain["imu0"][matrix].as<std::vector<std::vector<double>>>();
    ASSERT_EQ(rows.size(), 3u) << matrix;
    for (int row = 0; row < 3; ++row) {
      for (int column = 0; column < 3; ++column) EXPECT_EQ(rows[row][column], row == column ? 1.0 : 0.0) << matrix;
    }
  }
  EXPECT_EQ(chain["imu0"]["Tg"].as<std::vector<std::vector<double>>>()[1][1], 0.0);
  EXPECT_EQ(chain["imu0"]["T_i_b"].size(), 4u);
  const std::string reminder = "rostopic: /imu/raw  # the recording's topic (/imu/raw): set it to the one your IMU";
  EXPECT_NE(text.find("  " + reminder), std::string::npos) << text;
  EXPECT_NE(format_kalibr_imu_yaml(noise).find("\n" + reminder), std::string::npos) << format_kalibr_imu_yaml(noise);
}

// An anti-alias filter makes part of the white noise a Markov term with T_c below twice tau0:
// Kalibr's density adds it back in power; a slow Markov term (a real hump) stays out.
TEST(IdentifyKalibr, NoiseDensityAddsMarkovTermsFasterThanTau0InPower) {
  TriadFit gyro = hand_triad(SensorKind::kGyroscope, {2e-5, 2e-5, 2e-5}, {1e-7, 1e-7, 1e-7}, true);
  const double tau0_s = 0.005;
  const std::array<double, 3> correlation_time_s = {0.0018, 0.0099, 1.0};
  for (int axis = 0; axis < 3; ++axis) {
    TermEstimate markov;
    markov.name = "markov_1";
    markov.kind = TermKind::kMarkov;
    markov.status = TermStatus::kPresent;
    markov.amplitude.value = 3.8e-5;
    markov.shape.value = correlation_time_s[axis];
    gyro.axes[axis].terms.push_back(markov);
    gyro.axes[axis].points = {FitPoint{tau0_s, 1, 100.0}};
  }
  const double merged = std::sqrt(2e-5 * 2e-5 + 3.8e-5 * 3.8e-5);
  EXPECT_DOUBLE_EQ(white_equivalent_density(gyro.axes[0]), merged);
  EXPECT_DOUBLE_EQ(white_equivalent_density(gyro.axes[1]), merged);  // 9.9 ms < 2 tau0
  EXPECT_DOUBLE_EQ(white_equivalent_density(gyro.axes[2]), 2e-5);
  const KalibrImuNoise noise = kalibr_noise(gyro, gyro, 200.0, "/imu/raw");
  EXPECT_DOUBLE_EQ(noise.gyroscope_noise_density.value, merged);
  EXPECT_FALSE(noise.gyroscope_noise_density.is_upper_bound);
  // noise.yaml carries the same density per axis (the demo's index reads it from there).
  const auto values = read_noise_report_values(format_noise_report({gyro}, {"test", 100.0}));
  EXPECT_DOUBLE_EQ(values.at("triads.gyro.axes.gyro_x.white_equivalent.N_rad_s_per_sqrt_hz"), merged);
  EXPECT_DOUBLE_EQ(values.at("triads.gyro.axes.gyro_z.white_equivalent.N_rad_s_per_sqrt_hz"), 2e-5);

  // N absent (the fit gave all of it to the fast Markov term): the density is still a value.
  for (int axis = 0; axis < 3; ++axis) {
    gyro.axes[axis].terms[0].status = TermStatus::kAbsent;
    gyro.axes[axis].terms[0].amplitude.upper_bound = 1e-5;
  }
  const KalibrValue alone = kalibr_value(gyro, TermKind::kWhiteRate);
  EXPECT_DOUBLE_EQ(alone.value, 3.8e-5);
  EXPECT_FALSE(alone.is_upper_bound);
}

TEST(IdentifyPartialCurves, EachTermsCurveAndTheTotal) {
  const TriadFit triad = exact_triad(SensorKind::kGyroscope, 1e-4, 1e-6);
  const FitResult& fit = triad.axes[0];
  std::vector<allan::StabilityPoint> measured(2);
  measured[0].tau_s = 1.0;
  measured[0].deviation = 1e-4;
  measured[1].tau_s = 100.0;
  measured[1].deviation = 1e-5;
  const PartialCurves curves = partial_curves(fit, measured);
  ASSERT_EQ(curves.term_names, (std::vector<std::string>{"white_rate", "random_walk"}));
  const double n = fit.model.terms[0].amplitude, k = fit.model.terms[1].amplitude;
  EXPECT_DOUBLE_EQ(curves.term_deviations[0][1], n / 10.0);
  EXPECT_NEAR(curves.term_deviations[1][1], k * std::sqrt(100.0 / 3.0), 1e-18);
  EXPECT_NEAR(curves.total_deviation[1], std::hypot(curves.term_deviations[0][1], curves.term_deviations[1][1]), 1e-18);
  const std::string csv = format_partial_curves_csv(curves, "rad_s");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "tau_s,measured_dev_rad_s,fit_total_dev_rad_s,white_rate_dev_rad_s,"
            "random_walk_dev_rad_s,band95_low_rad_s,band95_high_rad_s");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
