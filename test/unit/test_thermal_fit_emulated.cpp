// The thermal fit against the emulator as oracle: fit on one thermal test (six positions at three
// soaks, 3 degC/min ramps, self-heating), check on held-out profiles the fit never saw.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "imu_lab/emulator/analytic_profile_avar.h"
#include "imu_lab/emulator/earth_model.h"
#include "thermal_test_support.h"

namespace imu_lab {
namespace {

using thermal_test::EffectSeries;

constexpr double kRateHz = 10.0;
constexpr double kWindowS = 60.0;
const char* const kChannel[6] = {"gyro x", "gyro y", "gyro z", "accelerometer x", "accelerometer y", "accelerometer z"};

thermal::ThermalFitOptions fit_options(bool rate_term) {
  thermal::ThermalFitOptions options;
  options.temperature_rate_term = rate_term;
  options.earth.latitude_rad = 50.45 * M_PI / 180.0;
  options.earth.gravity_m_s2 =
      emulator::normal_gravity_m_s2(EarthShape::kWgs84Rotating, options.earth.latitude_rad, 180.0);
  return options;
}

class ThermalFitEmulated : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    profile_ = new emulator::SensorProfile(
        emulator::load_sensor_profile(thermal_test::test_scenario("uncompensated_mems_gyro")));
    const auto fit_scenario = emulator::load_scenario(thermal_test::test_scenario("fit_multiposition"));
    const auto fit_run = thermal_test::emulate_thermal_run(*profile_, fit_scenario, 1, kRateHz);
    thermal::WindowSettings settings;
    settings.window_s = kWindowS;
    // The regime switch's default threshold from the fit's own temperature record (thermal_regime.h).
    regime_settings_.enabled = true;
    regime_settings_.threshold_c_s2 =
        thermal::suggest_regime_threshold(fit_run.temperature, regime_settings_.window_s).threshold_c_s2;
    thermal::RegimeIndicator indicator(regime_settings_);
    indicator.update_all(fit_run.temperature);
    // The second sensor and the regime are only read by the fits that ask for them.
    windows_ = new std::vector<thermal::ThermalWindow>(thermal_test::windows_of(fit_run, settings, true, &indicator));
    const auto& windows = *windows_;
    dynamic_ =
        new thermal::ThermalFitResult(thermal::fit_thermal_model(windows, settings.rate_window_s, fit_options(true)));
    static_only_ =
        new thermal::ThermalFitResult(thermal::fit_thermal_model(windows, settings.rate_window_s, fit_options(false)));
    thermal::ThermalFitOptions switched = fit_options(false);
    switched.regime_switch = regime_settings_;
    regime_switch_ =
        new thermal::ThermalFitResult(thermal::fit_thermal_model(windows, settings.rate_window_s, switched));
    fast_ramps_ = new thermal_test::ThermalRun(thermal_test::emulate_thermal_run(
        *profile_, emulator::load_scenario(thermal_test::test_scenario("fast_ramps")), 7, kRateHz));
  }
  static void TearDownTestSuite() {
    delete profile_;
    delete dynamic_;
    delete static_only_;
    delete regime_switch_;
    delete windows_;
    delete fast_ramps_;
  }
  static EffectSeries held_out(const std::string& scenario_path, const thermal::ThermalModel& model) {
    const auto scenario = emulator::load_scenario(scenario_path);
    return thermal_test::model_effect(thermal_test::emulate_thermal_run(*profile_, scenario, 7, kRateHz), model,
                                      kWindowS);
  }
  static double floor_of(int channel) {  // sqrt(AVAR(window)) of the profile's noise
    const auto& triad = channel < 3 ? profile_->gyro : profile_->accelerometer;
    return std::sqrt(emulator::analytic_axis_avar(triad, channel % 3, kWindowS, 1.0 / kRateHz));
  }
  static emulator::SensorProfile* profile_;
  static thermal::ThermalFitResult* dynamic_;
  static thermal::ThermalFitResult* static_only_;
  static thermal::ThermalFitResult* regime_switch_;
  static thermal::RegimeSwitchSettings regime_settings_;
  static std::vector<thermal::ThermalWindow>* windows_;  // of the fit run, with the second sensor and the regime
  static thermal_test::ThermalRun* fast_ramps_;          // held out (seed 7), shared by the fast-ramp tests
};
emulator::SensorProfile* ThermalFitEmulated::profile_ = nullptr;
thermal::ThermalFitResult* ThermalFitEmulated::dynamic_ = nullptr;
thermal::ThermalFitResult* ThermalFitEmulated::static_only_ = nullptr;
thermal::ThermalFitResult* ThermalFitEmulated::regime_switch_ = nullptr;
thermal::RegimeSwitchSettings ThermalFitEmulated::regime_settings_;
std::vector<thermal::ThermalWindow>* ThermalFitEmulated::windows_ = nullptr;
thermal_test::ThermalRun* ThermalFitEmulated::fast_ramps_ = nullptr;

// Peak-to-peak of the thermal effect on the held-out thermal_chamber profile over what the model
// leaves of it, per channel (printed).
std::array<double, 6> held_out_reduction(const EffectSeries& effect, const char* label) {
  std::array<double, 6> ratios{};
  for (int channel = 0; channel < 6; ++channel) {
    std::vector<double> truth, left;
    for (std::size_t w = 0; w < effect.truth.size(); ++w) {
      truth.push_back(effect.truth[w][channel]);
      left.push_back(effect.truth[w][channel] - effect.removed[w][channel]);
    }
    const double before = thermal_test::peak_to_peak(truth), after = thermal_test::peak_to_peak(left);
    ratios[channel] = before / after;
    std::printf("%s%-16s thermal peak-to-peak %.3g before, %.3g after: %.0fx\n", label, kChannel[channel], before,
                after, ratios[channel]);
  }
  return ratios;
}

TEST_F(ThermalFitEmulated, HeldOutProfileThermalVariationReducedTwentyFold) {
  const auto ratios =
      held_out_reduction(held_out(thermal_test::shipped_scenario("thermal_chamber"), dynamic_->model), "");
  for (int channel = 0; channel < 6; ++channel) EXPECT_GT(ratios[channel], 20.0) << kChannel[channel];
  EXPECT_TRUE(dynamic_->warnings.empty()) << dynamic_->warnings.front();
}

// The same test turned by hand (hand_turned_multiposition.yaml: each revisit off by up to 0.4 deg):
// across gravity a revisit then differs by ~g * 0.4 deg, several mg. One constant per orientation
// compared such revisits and lost the accelerometer model (1.2-2.2x on the held-out profile, exit
// 0, no warning); one constant per visit for the axes across gravity keeps it, and the comparison,
// when claimed (precise_revisits), is now warned about.
TEST_F(ThermalFitEmulated, AHandTurnedTestKeepsTheAccelerometerModel) {
  const auto scenario = emulator::load_scenario(thermal_test::test_scenario("hand_turned_multiposition"));
  const auto run = thermal_test::emulate_thermal_run(*profile_, scenario, 1, kRateHz);
  thermal::WindowSettings settings;
  settings.window_s = kWindowS;
  const auto windows = thermal_test::windows_of(run, settings, false);
  const auto per_visit = thermal::fit_thermal_model(windows, settings.rate_window_s, fit_options(true));
  thermal::ThermalFitOptions precise = fit_options(true);
  precise.precise_revisits = true;
  const auto per_orientation = thermal::fit_thermal_model(windows, settings.rate_window_s, precise);
  const std::string chamber = thermal_test::shipped_scenario("thermal_chamber");
  const auto kept = held_out_reduction(held_out(chamber, per_visit.model), "hand-turned, per visit:       ");
  const auto lost = held_out_reduction(held_out(chamber, per_orientation.model), "hand-turned, per orientation: ");
  for (int channel = 3; channel < 6; ++channel) {
    EXPECT_GT(kept[channel], 20.0) << kChannel[channel];
    EXPECT_GT(kept[channel], 5.0 * lost[channel]) << kChannel[channel];
  }
  EXPECT_LT(std::max(lost[3], lost[4]), 5.0) << "the hand-turned test would not show the problem";
  EXPECT_TRUE(per_visit.warnings.empty()) << per_visit.warnings.front();
  ASSERT_FALSE(per_orientation.warnings.empty());
  EXPECT_NE(per_orientation.warnings.front().find("chi2/dof"), std::string::npos) << per_orientation.warnings.front();
  for (int channel = 0; channel < 6; ++channel) {
    std::printf("hand-turned %-16s residual / window noise: per visit %.3g, per orientation %.3g\n", kChannel[channel],
                per_visit.axes[channel].residual_over_noise, per_orientation.axes[channel].residual_over_noise);
  }
}

// The fit's residual (window means around the model) is the averaging window's noise floor,
// sqrt(AVAR(60 s)) of the profile, plus what AVAR at 60 s does not see: the rate random walk
// and flicker wander over the 3.7 h test. Below the floor would mean fitting the noise.
TEST_F(ThermalFitEmulated, ResidualIsAtTheWindowNoiseFloor) {
  for (int channel = 0; channel < 6; ++channel) {
    const double residual = dynamic_->axes[channel].residual_rms, floor = floor_of(channel);
    std::printf("%-16s residual rms %.3g, floor sqrt(AVAR(%g s)) %.3g: %.2fx\n", kChannel[channel], residual, kWindowS,
                floor, residual / floor);
    EXPECT_GT(residual, 0.8 * floor) << kChannel[channel];
    EXPECT_LT(residual, 2.0 * floor) << kChannel[channel];
  }
}

// The residual (window means of the model error, their mean removed: a constant is calibration's)
// on held-out data, over all windows or those with |dT/dt| above 0.01 degC/s (the ramps).
double held_out_rms(const EffectSeries& effect, int channel, bool ramps_only) {
  double mean = 0.0;
  for (std::size_t w = 0; w < effect.truth.size(); ++w) mean += effect.truth[w][channel] - effect.removed[w][channel];
  mean /= effect.truth.size();
  double square = 0.0;
  int count = 0;
  for (std::size_t w = 0; w < effect.truth.size(); ++w) {
    if (ramps_only && std::abs(effect.rate_c_s[w]) < 0.01) continue;
    const double error = effect.truth[w][channel] - effect.removed[w][channel] - mean;
    square += error * error;
    ++count;
  }
  return std::sqrt(square / count);
}

// Golovach 2017 Fig. 3.17: a static polynomial leaves residuals where the temperature changes fast.
TEST_F(ThermalFitEmulated, RateTermShrinksTheResidualInFastRamps) {
  const EffectSeries with_rate = thermal_test::model_effect(*fast_ramps_, dynamic_->model, kWindowS);
  const EffectSeries without = thermal_test::model_effect(*fast_ramps_, static_only_->model, kWindowS);
  for (int channel = 3; channel < 6; ++channel) {  // the accelerometers carry the dynamic-regime term
    const double dynamic = held_out_rms(with_rate, channel, true), static_only = held_out_rms(without, channel, true);
    std::printf("%-16s model error in ramps: %.3g static-only, %.3g with the rate term (%.1fx)\n", kChannel[channel],
                static_only, dynamic, static_only / dynamic);
    EXPECT_LT(dynamic, 0.5 * static_only) << kChannel[channel];
  }
}

// Golovach 2017 eqs. 3.18, 3.19 against the additive rate term on the held-out fast ramps. The
// emulator's thermal truth is a polynomial in T plus an additive term in dT/dt: the rate term is
// that physics. The switch alone fits a second polynomial in T to the dynamic regime, which cannot
// follow a bias proportional to dT/dt (ramps up and down pass the same T); with the second,
// lagging sensor in its terms (eq. 4.1: the dynamic coefficients are in the ADC board's sensor)
// it can, as T - T2 ~ tau2 dT2/dt. Figures in doc/thermal.md.
TEST_F(ThermalFitEmulated, RegimeSwitchAgainstTheRateTermOnTheFastRamps) {
  const auto fit = [&](bool second_sensor, bool regime_switch) {
    thermal::ThermalFitOptions options = fit_options(false);
    options.second_sensor_term = second_sensor;
    if (regime_switch) options.regime_switch = regime_settings_;
    return thermal::fit_thermal_model(*windows_, 60.0, options).model;
  };
  const auto effect = [&](const thermal::ThermalModel& model) {
    return thermal_test::model_effect(*fast_ramps_, model, kWindowS);
  };
  const EffectSeries polynomial = effect(static_only_->model), rate_term = effect(dynamic_->model),
                     switched = effect(regime_switch_->model), second = effect(fit(true, false)),
                     switched_second = effect(fit(true, true));
  double dynamic_windows = 0.0;
  for (double fraction : switched.dynamic_fraction) dynamic_windows += fraction;
  std::printf("regime switch: threshold %.3g degC/s^2, window %g s, hold %g s; %.0f of %zu held-out windows dynamic\n",
              regime_settings_.threshold_c_s2, regime_settings_.window_s, regime_settings_.hold_s, dynamic_windows,
              switched.truth.size());
  for (int channel = 0; channel < 6; ++channel) {
    for (const bool ramps : {false, true}) {
      std::printf(
          "%-16s held-out rms %s: polynomial %.3g, + rate term %.3g, regime switch %.3g, second sensor %.3g, "
          "switch + second sensor %.3g\n",
          kChannel[channel], ramps ? "in ramps  " : "all windows", held_out_rms(polynomial, channel, ramps),
          held_out_rms(rate_term, channel, ramps), held_out_rms(switched, channel, ramps),
          held_out_rms(second, channel, ramps), held_out_rms(switched_second, channel, ramps));
    }
    if (channel < 3) continue;  // the accelerometers carry a dynamic-regime effect 20x their noise
    // The switch with the lagging sensor removes most of the dynamic error (0.25-0.28 on this seed).
    EXPECT_LT(held_out_rms(switched_second, channel, true), 0.5 * held_out_rms(polynomial, channel, true));
    // ... and the rate term, being the emulator's physics, does better still (0.05-0.07 of the
    // polynomial's; the switch alone 0.9-1.0).
    EXPECT_LT(held_out_rms(rate_term, channel, true), 0.5 * held_out_rms(switched_second, channel, true));
  }
  EXPECT_GT(dynamic_windows, 5.0);
}

TEST_F(ThermalFitEmulated, FindsTheSixOrientationsAndTheScaleFactorSlope) {
  EXPECT_EQ(dynamic_->orientations.clusters.size(), 6u);
  const auto& truth = profile_->accelerometer.thermal.scale_factor_polynomial_ppm[0];
  for (int axis = 0; axis < 3; ++axis) {
    const auto& report = dynamic_->axes[3 + axis];
    ASSERT_GE(report.scale_factor_order, 1);
    const auto* slope = &report.parameters.front();
    for (const auto& p : report.parameters) {
      if (p.name == "scale_factor_polynomial_ppm[0]") slope = &p;
    }
    EXPECT_EQ(slope->name, "scale_factor_polynomial_ppm[0]");
    EXPECT_GT(slope->sigma, 0.0);
    EXPECT_NEAR(slope->value, truth[axis], 1.0) << kChannel[3 + axis];  // ppm/degC; the profile's is 20..30
  }
}

// Golovach 2017 eq. 4.1: the scale factor also follows the second, lagging thermosensor (the ADC
// board). The truth gets such a term (and no rate terms: T - T2 ~ tau2 dT2/dt, so a rate term
// and the lagging sensor carry nearly the same information, and this test isolates the latter).
// Fitted on the tumbling test (every axis up and down while T and T2 differ by up to ~10 degC),
// checked against the truth within its sigmas and applied on the held-out fast ramps.
TEST(ThermalFitSecondSensor, RecoversTheScaleFactorInTheSecondSensorAndRemovesIt) {
  auto profile = emulator::load_sensor_profile(thermal_test::test_scenario("uncompensated_mems_gyro"));
  for (auto* thermal : {&profile.gyro.thermal, &profile.accelerometer.thermal}) {
    thermal->bias_per_temperature_rate.setZero();
    thermal->scale_factor_ppm_per_temperature_rate.setZero();
  }
  const Eigen::Vector3d truth_ppm_per_c(10.0, -8.0, 12.0);
  profile.accelerometer.thermal.scale_factor_second_sensor_polynomial_ppm = {truth_ppm_per_c};
  const double rate_hz = 5.0;  // 36000 samples: 60 s windows of 300 samples still reach the floor
  const auto run = thermal_test::emulate_thermal_run(
      profile, emulator::load_scenario(thermal_test::test_scenario("tumbling_second_sensor")), 1, rate_hz);
  thermal::WindowSettings settings;
  settings.window_s = kWindowS;
  const auto windows = thermal_test::windows_of(run, settings, true);
  thermal::ThermalFitOptions options = fit_options(false);
  options.polynomial_order = 2;  // the truth's bias order (its scale factor is order 1)
  options.second_sensor_term = true;
  options.precise_revisits = true;  // the emulator repeats each orientation exactly
  thermal::ThermalFitOptions with_scale = options;
  with_scale.second_sensor_scale_factor = true;
  const auto without = thermal::fit_thermal_model(windows, settings.rate_window_s, options);
  const auto with = thermal::fit_thermal_model(windows, settings.rate_window_s, with_scale);
  for (int axis = 0; axis < 3; ++axis) {
    const auto& parameters = with.axes[3 + axis].parameters;
    const auto found = std::find_if(parameters.begin(), parameters.end(), [](const thermal::FittedParameter& p) {
      return p.name == "scale_factor_second_sensor_polynomial_ppm[0]";
    });
    ASSERT_NE(found, parameters.end());
    std::printf("%-16s second-sensor scale factor %.3f +- %.3f ppm/degC (truth %.1f)\n", kChannel[3 + axis],
                found->value, found->sigma, truth_ppm_per_c[axis]);
    // 4 sigma: the sigmas assume independent window means, which the flicker and random walk make
    // somewhat optimistic (thermal_fit.h); the term is resolved to better than a fifth of itself.
    EXPECT_NEAR(found->value, truth_ppm_per_c[axis], 4.0 * found->sigma) << kChannel[3 + axis];
    EXPECT_LT(found->sigma, 0.2 * std::abs(truth_ppm_per_c[axis])) << kChannel[3 + axis];
    EXPECT_EQ(with.model.accelerometer[axis].scale_factor_second_sensor_polynomial_ppm.front(), found->value);
  }
  // Applied on a held-out profile (fast ramps, z up: z sees the scale factor as a bias change).
  const auto held_out_run = thermal_test::emulate_thermal_run(
      profile, emulator::load_scenario(thermal_test::test_scenario("fast_ramps")), 7, rate_hz);
  const EffectSeries kept = thermal_test::model_effect(held_out_run, with.model, kWindowS);
  const EffectSeries lost = thermal_test::model_effect(held_out_run, without.model, kWindowS);
  std::vector<double> truth;
  for (const auto& w : kept.truth) truth.push_back(w[5]);
  const double rms_with = held_out_rms(kept, 5, false), rms_without = held_out_rms(lost, 5, false);
  std::printf("accelerometer z held-out model error rms: %.3g without the term, %.3g with it (effect p-p %.3g)\n",
              rms_without, rms_with, thermal_test::peak_to_peak(truth));
  EXPECT_LT(rms_with, 0.5 * rms_without);
  EXPECT_LT(rms_with, 2.0 * std::sqrt(emulator::analytic_axis_avar(profile.accelerometer, 2, kWindowS, 1.0 / rate_hz)));
}

}  // namespace
}  // namespace imu_lab
