// The regime switch (Golovach 2017 eqs. 3.18, 3.19) and the second thermosensor in the scale
// factor (eq. 4.1): the regime indicator on a temperature profile with known switch times, the
// live indicator against the offline one, the default threshold, the model's switch, the YAML
// keys, and what is refused. The fits on emulated truth are in test_thermal_fit_emulated.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/thermal/thermal_compensator.h"
#include "imu_lab/thermal/thermal_fit.h"
#include "imu_lab/thermal/thermal_model_yaml.h"
#include "imu_lab/thermal/thermal_regime.h"

namespace imu_lab {
namespace {

constexpr std::int64_t kStartNs = 1'000'000'000'000'000'000;  // stamps near 1e9 s, as a bag's
constexpr double kCurvature_c_s2 = 1e-4;

// d2T/dt2 = +a on [1000, 1600) s, 0 on [1600, 2400), -a on [2400, 3000), 0 elsewhere: a soak, a
// ramp that starts, holds at 0.06 degC/s and stops (switch times 1000, 1600, 2400, 3000 s).
double profile_c(double t) {
  const double a = kCurvature_c_s2;
  if (t < 1000.0) return 20.0;
  if (t < 1600.0) return 20.0 + 0.5 * a * (t - 1000.0) * (t - 1000.0);
  const double at_1600 = 20.0 + 0.5 * a * 600.0 * 600.0, rate = a * 600.0;
  if (t < 2400.0) return at_1600 + rate * (t - 1600.0);
  const double at_2400 = at_1600 + rate * 800.0;
  if (t < 3000.0) return at_2400 + rate * (t - 2400.0) - 0.5 * a * (t - 2400.0) * (t - 2400.0);
  return at_2400 + rate * 600.0 - 0.5 * a * 600.0 * 600.0;
}

std::int64_t stamp_at(double t) { return kStartNs + stamp_ns_from_seconds(t); }

thermal::TemperatureHistory profile_history() {
  thermal::TemperatureHistory history;
  for (int k = 0; k <= 4000; ++k) history.add(stamp_at(k), profile_c(k));  // 1 Hz
  return history;
}

thermal::RegimeSwitchSettings settings(double threshold_c_s2, double window_s, double hold_s) {
  thermal::RegimeSwitchSettings s;
  s.enabled = true;
  s.threshold_c_s2 = threshold_c_s2;
  s.window_s = window_s;
  s.hold_s = hold_s;
  return s;
}

TEST(ThermalRegime, SecondDerivativeIsExactForAParabola) {
  const auto history = profile_history();
  EXPECT_NEAR(history.second_derivative_at(stamp_at(1500.0), 300.0), kCurvature_c_s2, 1e-10);
  EXPECT_NEAR(history.second_derivative_at(stamp_at(2300.0), 300.0), 0.0, 1e-10);
  EXPECT_NEAR(history.second_derivative_at(stamp_at(2950.0), 300.0), -kCurvature_c_s2, 1e-10);
  EXPECT_EQ(history.second_derivative_at(stamp_at(100.0), 300.0), 0.0);  // not a full window yet
}

// The estimate is the curvature averaged by a kernel symmetric about the window's middle, so a
// step of d2T/dt2 crosses half its height W/2 after the step; the regime then lasts hold_s longer.
TEST(ThermalRegime, IndicatorSwitchesHalfAWindowAfterTheCurvatureAndHolds) {
  const double window_s = 300.0, hold_s = 120.0;
  thermal::RegimeIndicator indicator(settings(0.5 * kCurvature_c_s2, window_s, hold_s));
  indicator.update_all(profile_history());
  const double delay_s = 0.5 * window_s;
  struct Switch {
    double at_s;
    bool to_dynamic;
  };
  // Off switches come hold_s after the estimate falls below the threshold.
  const Switch switches[] = {{1000.0 + delay_s, true},
                             {1600.0 + delay_s + hold_s, false},
                             {2400.0 + delay_s, true},
                             {3000.0 + delay_s + hold_s, false}};
  for (const Switch& s : switches) {
    // One reading (1 s) either side of the expected time, and a margin of 2 s for the kernel's
    // discrete sampling.
    EXPECT_EQ(indicator.dynamic_at(stamp_at(s.at_s - 3.0)), !s.to_dynamic) << s.at_s;
    EXPECT_EQ(indicator.dynamic_at(stamp_at(s.at_s + 3.0)), s.to_dynamic) << s.at_s;
  }
  EXPECT_FALSE(indicator.dynamic_at(stamp_at(500.0)));
  EXPECT_FALSE(indicator.dynamic_at(stamp_at(2000.0)));  // the steady part of the ramp is static
  EXPECT_FALSE(indicator.dynamic_at(stamp_at(3900.0)));
  EXPECT_FALSE(indicator.dynamic_at(kStartNs - 1));  // before any reading
}

// The node feeds the indicator reading by reading and forgets old readings; the fit feeds it the
// whole history. Both must give the same regime at every stamp.
TEST(ThermalRegime, LiveIndicatorAgreesWithTheOfflineOne) {
  const auto s = settings(0.5 * kCurvature_c_s2, 300.0, 60.0);
  thermal::RegimeIndicator offline(s), live(s);
  offline.update_all(profile_history());
  thermal::TemperatureHistory history;
  int disagreements = 0, dynamic = 0;
  for (int k = 0; k <= 4000; ++k) {
    history.add(stamp_at(k), profile_c(k));
    live.update(history);
    const std::int64_t probe_ns = stamp_at(k + 0.5);  // between readings, as IMU samples are
    if (live.dynamic_at(probe_ns) != offline.dynamic_at(probe_ns)) ++disagreements;
    if (offline.dynamic_at(probe_ns)) ++dynamic;
    history.drop_before(stamp_at(k - 400.0));  // the compensator keeps one window and a margin
    live.drop_before(stamp_at(k - 400.0));
  }
  EXPECT_EQ(disagreements, 0);
  EXPECT_GT(dynamic, 1000);
}

// The default threshold on a steady temperature with white noise: the estimate's predicted noise
// sqrt(6 / n) sigma / (W/3)^2 matches the spread of the estimates, and 5 of it is not crossed.
TEST(ThermalRegime, DefaultThresholdIsAboveTheEstimatesNoise) {
  std::mt19937_64 random(19);
  std::normal_distribution<double> noise(0.0, 0.05);
  thermal::TemperatureHistory history;
  for (int k = 0; k < 20000; ++k) history.add(stamp_at(k), 25.0 + noise(random));
  const double window_s = 300.0;
  const auto suggestion = thermal::suggest_regime_threshold(history, window_s);
  const double predicted = std::sqrt(6.0 / 100.0) * 0.05 / (100.0 * 100.0);
  EXPECT_NEAR(suggestion.noise_c_s2, predicted, 0.05 * predicted);  // sigma from 20000 readings: ~1 %
  double square = 0.0;
  int count = 0;
  for (int k = 400; k < 20000; ++k) {
    const double value = history.second_derivative_at(stamp_at(k), window_s);
    square += value * value;
    ++count;
  }
  // The estimates overlap (correlated), so their spread is known to ~10 % from 20000 of them.
  EXPECT_NEAR(std::sqrt(square / count), predicted, 0.15 * predicted);
  EXPECT_NEAR(suggestion.threshold_c_s2, 5.0 * suggestion.noise_c_s2, 1e-15);  // the noise decides
  thermal::RegimeIndicator indicator(settings(suggestion.threshold_c_s2, window_s, 0.0));
  indicator.update_all(history);
  EXPECT_EQ(indicator.readings_over_threshold(), 0u) << suggestion.text();
  // A noise-free profile: a tenth of its sharpest curvature.
  const auto clean = thermal::suggest_regime_threshold(profile_history(), window_s);
  EXPECT_NEAR(clean.peak_c_s2, kCurvature_c_s2, 1e-9);
  EXPECT_NEAR(clean.threshold_c_s2, 0.1 * kCurvature_c_s2, 1e-9);
}

std::string invalid_argument_of(const thermal::RegimeSwitchSettings& s) {
  try {
    thermal::RegimeIndicator indicator(s);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(ThermalRegime, RefusesBadSettings) {
  EXPECT_NE(invalid_argument_of(settings(0.0, 300.0, 0.0)).find("threshold on |d2T/dt2| must be a positive"),
            std::string::npos);
  EXPECT_NE(invalid_argument_of(settings(-1e-6, 300.0, 0.0)).find("got -1e-06"), std::string::npos);
  EXPECT_NE(invalid_argument_of(settings(1e-6, 0.0, 0.0)).find("window must be positive"), std::string::npos);
  EXPECT_NE(invalid_argument_of(settings(1e-6, 300.0, -1.0)).find("hold time must be 0 s or more"), std::string::npos);
  EXPECT_EQ(invalid_argument_of(settings(1e-6, 300.0, 0.0)), "");
}

thermal::ThermalModel switched_model() {
  thermal::ThermalModel model;
  model.reference_temperature_c = 20.0;
  model.uses_second_sensor = true;
  model.validity = {-20.0, 60.0, 0.0, 0.0, -20.0, 60.0};
  model.regime_switch = settings(2e-5, 240.0, 30.0);
  for (int axis = 0; axis < 3; ++axis) {
    model.accelerometer[axis].bias_polynomial = {1e-3, -1e-5};
    model.accelerometer[axis].scale_factor_polynomial_ppm = {30.0};
    model.accelerometer[axis].scale_factor_second_sensor_polynomial_ppm = {-12.0, 0.25};
    model.dynamic_accelerometer[axis] = model.accelerometer[axis];
    model.dynamic_accelerometer[axis].bias_polynomial = {2e-3};
    model.dynamic_accelerometer[axis].bias_second_sensor_polynomial = {-1e-3};
    model.gyro[axis].bias_polynomial = {1e-6};
    model.dynamic_gyro[axis].bias_polynomial = {3e-6};
  }
  return model;
}

TEST(ThermalRegime, ModelAppliesTheRegimesTermsAndTheSecondSensorScaleFactor) {
  const auto model = switched_model();
  const Eigen::Vector3d truth(0.0, 0.0, 9.8);
  const double dt = 10.0, dt2 = 4.0;  // T = 30, T2 = 24 degC
  const double scale = 1e-6 * (30.0 * dt - 12.0 * dt2 + 0.25 * dt2 * dt2);
  for (const bool dynamic : {false, true}) {
    const double bias = dynamic ? 2e-3 * dt - 1e-3 * dt2 : 1e-3 * dt - 1e-5 * dt * dt;
    const Eigen::Vector3d raw = truth * (1.0 + scale) + Eigen::Vector3d::Constant(bias);
    thermal::ThermalInput input{30.0, 0.0, 24.0};
    input.dynamic_regime = dynamic;
    const auto corrected = thermal::correct(model, Eigen::Vector3d::Zero(), raw, input);
    EXPECT_LT((corrected.specific_force_m_s2 - truth).norm(), 1e-12) << dynamic;
    EXPECT_NEAR(corrected.angular_rate_rad_s[0], -(dynamic ? 3e-6 : 1e-6) * dt, 1e-15);
  }
  // Without the switch, the dynamic flag changes nothing.
  auto plain = model;
  plain.regime_switch.enabled = false;
  thermal::ThermalInput input{30.0, 0.0, 24.0};
  const auto a = thermal::correct(plain, Eigen::Vector3d::Zero(), truth, input);
  input.dynamic_regime = true;
  EXPECT_EQ(thermal::correct(plain, Eigen::Vector3d::Zero(), truth, input).specific_force_m_s2, a.specific_force_m_s2);
}

// The compensator feeds its indicator from the temperature topic and applies the dynamic terms
// exactly where the offline indicator says so.
TEST(ThermalRegime, CompensatorSwitchesWhereTheIndicatorDoes) {
  auto model = switched_model();
  model.uses_second_sensor = false;
  model.validity = {-100.0, 200.0, 0.0, 0.0, 0.0, 0.0};
  model.regime_switch = settings(0.5 * kCurvature_c_s2, 300.0, 0.0);
  for (int axis = 0; axis < 3; ++axis) {
    model.accelerometer[axis].scale_factor_second_sensor_polynomial_ppm.clear();
    model.dynamic_accelerometer[axis].scale_factor_second_sensor_polynomial_ppm.clear();
    model.dynamic_accelerometer[axis].bias_second_sensor_polynomial.clear();
  }
  thermal::RegimeIndicator offline(model.regime_switch);
  offline.update_all(profile_history());
  thermal::ThermalCompensator compensator(model, 1.0);
  std::vector<thermal::CompensatedSample> ready;
  for (int k = 0; k <= 4000; ++k) {
    compensator.add_temperature(stamp_at(k), profile_c(k), &ready);
    io::ImuRecord reading;
    reading.stamp_ns = stamp_at(k + 0.5);
    reading.specific_force_m_s2 = Eigen::Vector3d(0.0, 0.0, 9.8);
    compensator.add_imu(reading, &ready);
  }
  compensator.flush(&ready);
  ASSERT_EQ(ready.size(), 4001u);
  int dynamic = 0;
  for (const auto& sample : ready) {
    EXPECT_EQ(sample.input.dynamic_regime, offline.dynamic_at(sample.corrected.stamp_ns));
    dynamic += sample.input.dynamic_regime;
  }
  EXPECT_GT(dynamic, 1000);
}

TEST(ThermalRegime, YamlRoundTripWithTheNewKeysAndOldFilesStillLoad) {
  const auto model = switched_model();
  const std::string path = ::testing::TempDir() + "thermal_model_regime.yaml";
  thermal::save_thermal_model(path, model, nullptr);
  const auto loaded = thermal::load_thermal_model(path);
  ASSERT_TRUE(loaded.regime_switch.enabled);
  EXPECT_EQ(loaded.regime_switch.threshold_c_s2, 2e-5);
  EXPECT_EQ(loaded.regime_switch.window_s, 240.0);
  EXPECT_EQ(loaded.regime_switch.hold_s, 30.0);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(loaded.accelerometer[axis].scale_factor_second_sensor_polynomial_ppm,
              model.accelerometer[axis].scale_factor_second_sensor_polynomial_ppm);
    EXPECT_EQ(loaded.dynamic_accelerometer[axis].bias_polynomial, model.dynamic_accelerometer[axis].bias_polynomial);
    EXPECT_EQ(loaded.dynamic_accelerometer[axis].bias_second_sensor_polynomial,
              model.dynamic_accelerometer[axis].bias_second_sensor_polynomial);
    EXPECT_EQ(loaded.dynamic_gyro[axis].bias_polynomial, model.dynamic_gyro[axis].bias_polynomial);
  }
  EXPECT_EQ(thermal::thermal_model_to_yaml(loaded, nullptr), thermal::thermal_model_to_yaml(model, nullptr));
  // A model without the new terms is written without the new keys (files as before).
  auto plain = model;
  plain.regime_switch = {};
  for (int axis = 0; axis < 3; ++axis) plain.accelerometer[axis].scale_factor_second_sensor_polynomial_ppm.clear();
  const std::string text = thermal::thermal_model_to_yaml(plain, nullptr);
  EXPECT_EQ(text.find("regime_switch"), std::string::npos);
  EXPECT_EQ(text.find("dynamic_"), std::string::npos);
  EXPECT_EQ(text.find("scale_factor_second_sensor"), std::string::npos);
  // A file written before these keys existed.
  const auto old =
      thermal::load_thermal_model(std::string(IMU_LAB_TEST_DATA_DIR) + "/thermal/model_uncompensated_mems_gyro.yaml");
  EXPECT_FALSE(old.regime_switch.enabled);
  EXPECT_TRUE(old.accelerometer[2].scale_factor_second_sensor_polynomial_ppm.empty());
}

std::string config_error_of(const std::string& text) {
  const std::string path = ::testing::TempDir() + "thermal_model_regime_bad.yaml";
  {
    std::FILE* file = std::fopen(path.c_str(), "w");
    std::fputs(text.c_str(), file);
    std::fclose(file);
  }
  try {
    thermal::load_thermal_model(path);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(ThermalRegime, YamlRefusesBadRegimeSections) {
  const std::string good = thermal::thermal_model_to_yaml(switched_model(), nullptr);
  // The line that starts with `key` (after indentation) replaced by `line`.
  const auto replaced = [&](const std::string& key, const std::string& line) {
    std::string text = good;
    const auto at = text.find(key);
    EXPECT_NE(at, std::string::npos) << key;
    return text.replace(at, text.find('\n', at) - at, line);
  };
  EXPECT_NE(config_error_of(replaced("threshold_c_s2:", "threshold_c_s2: 0")).find("regime_switch.threshold_c_s2"),
            std::string::npos);
  EXPECT_NE(config_error_of(replaced("hold_s:", "hold_s: -5")).find("regime_switch.hold_s: must be 0 s or more"),
            std::string::npos);
  EXPECT_NE(config_error_of(replaced("regime_switch:", "regime_switch_off:")).find("regime_switch_off"),
            std::string::npos);  // unknown key
  // Dynamic terms without the switch section.
  const auto start = good.find("regime_switch:"), end = good.find("dynamic_gyro:");
  std::string orphan = good;
  orphan.erase(start, end - start);
  EXPECT_NE(config_error_of(orphan).find("dynamic_gyro: the dynamic regime's terms need a regime_switch section"),
            std::string::npos);
}

// Static windows, six positions, the temperature rising; `dynamic_every` > 0 marks every n-th
// window dynamic (fraction 1).
std::vector<thermal::ThermalWindow> regime_windows(int per_orientation, int dynamic_every) {
  const std::vector<Eigen::Vector3d> ups = {Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(),
                                            Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitY(),
                                            Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()};
  std::vector<thermal::ThermalWindow> windows;
  for (const Eigen::Vector3d& up : ups) {
    for (int i = 0; i < per_orientation; ++i) {
      thermal::ThermalWindow w;
      w.temperature_c = -20.0 + 80.0 * i / (per_orientation - 1);
      w.mid_stamp_s = 60.0 * windows.size();
      const bool dynamic = dynamic_every > 0 && i % dynamic_every == 0;
      w.dynamic_fraction = dynamic ? 1.0 : 0.0;
      const double bias = (dynamic ? 3e-4 : 1e-4) * (w.temperature_c - 20.0) + (i % 2 ? 1e-5 : -1e-5);
      w.mean_specific_force_m_s2 = 9.8 * up + Eigen::Vector3d::Constant(bias);
      w.is_static = true;
      w.sample_count = 600;
      windows.push_back(w);
    }
  }
  return windows;
}

std::string fit_refusal(const std::vector<thermal::ThermalWindow>& windows, const thermal::ThermalFitOptions& options) {
  try {
    thermal::fit_thermal_model(windows, 60.0, options);
  } catch (const thermal::ThermalFitError& error) {
    return error.what();
  }
  return "";
}

thermal::ThermalFitOptions regime_options(double threshold_c_s2) {
  thermal::ThermalFitOptions options;
  options.polynomial_order = 1;
  options.regime_switch = settings(threshold_c_s2, 300.0, 0.0);
  return options;
}

// Truth with a switch (slope 1e-4 static, 3e-4 dynamic): the switched fit recovers both regimes,
// and its residual is the windows' +-1e-5 while one polynomial leaves the regimes' difference.
TEST(ThermalRegime, FitRecoversEachRegimesBiasAndSharesTheRest) {
  const auto windows = regime_windows(40, 3);
  const auto result = thermal::fit_thermal_model(windows, 60.0, regime_options(1e-5));
  thermal::ThermalFitOptions plain = regime_options(1e-5);
  plain.regime_switch.enabled = false;
  const auto single = thermal::fit_thermal_model(windows, 60.0, plain);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_LT(result.axes[3 + axis].residual_rms, 1.1e-5);
    EXPECT_GT(single.axes[3 + axis].residual_rms, 10.0 * result.axes[3 + axis].residual_rms);
  }
  ASSERT_TRUE(result.model.regime_switch.enabled);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(result.model.accelerometer[axis].bias_polynomial[0], 1e-4, 2e-6);
    EXPECT_NEAR(result.model.dynamic_accelerometer[axis].bias_polynomial[0], 3e-4, 2e-6);
    EXPECT_EQ(result.model.dynamic_accelerometer[axis].scale_factor_polynomial_ppm,
              result.model.accelerometer[axis].scale_factor_polynomial_ppm);
  }
  bool named = false;
  for (const auto& p : result.axes[3].parameters) named = named || p.name == "dynamic.bias_polynomial[0]";
  EXPECT_TRUE(named);
}

TEST(ThermalRegime, FitRefusesAnEmptyRegimeAndBadSettingsClearly) {
  // No window in the dynamic regime.
  const std::string empty = fit_refusal(regime_windows(40, 0), regime_options(1e-5));
  EXPECT_NE(empty.find("gyro x: the dynamic regime (|d2T/dt2| above 1e-05 degC/s^2, hold 0 s) holds 0 "
                       "static windows"),
            std::string::npos)
      << empty;
  EXPECT_NE(empty.find("lower the threshold"), std::string::npos) << empty;
  // Too few in the static one (every window dynamic).
  const std::string thin = fit_refusal(regime_windows(40, 1), regime_options(1e-5));
  EXPECT_NE(thin.find("the static regime"), std::string::npos) << thin;
  EXPECT_NE(thin.find("raise the threshold"), std::string::npos) << thin;
  EXPECT_NE(fit_refusal(regime_windows(40, 3), regime_options(0.0)).find("must be a positive number of degC/s^2"),
            std::string::npos);
  // Windows averaged without the indicator.
  auto windows = regime_windows(40, 3);
  for (auto& w : windows) w.dynamic_fraction.reset();
  EXPECT_NE(fit_refusal(windows, regime_options(1e-5)).find("windows averaged with the regime indicator"),
            std::string::npos);
  // The second-sensor scale factor without the second sensor.
  thermal::ThermalFitOptions options;
  options.second_sensor_scale_factor = true;
  EXPECT_NE(fit_refusal(regime_windows(40, 0), options).find("needs the second-sensor term"), std::string::npos);
}

}  // namespace
}  // namespace imu_lab
