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
    const auto windows = thermal_test::windows_of(fit_run, settings, false);
    dynamic_ =
        new thermal::ThermalFitResult(thermal::fit_thermal_model(windows, settings.rate_window_s, fit_options(true)));
    static_only_ =
        new thermal::ThermalFitResult(thermal::fit_thermal_model(windows, settings.rate_window_s, fit_options(false)));
  }
  static void TearDownTestSuite() {
    delete profile_;
    delete dynamic_;
    delete static_only_;
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
};
emulator::SensorProfile* ThermalFitEmulated::profile_ = nullptr;
thermal::ThermalFitResult* ThermalFitEmulated::dynamic_ = nullptr;
thermal::ThermalFitResult* ThermalFitEmulated::static_only_ = nullptr;

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

// Seed 001 Fig. 3.17: a static polynomial leaves residuals where the temperature changes fast.
TEST_F(ThermalFitEmulated, RateTermShrinksTheResidualInFastRamps) {
  const std::string fast = thermal_test::test_scenario("fast_ramps");
  const EffectSeries with_rate = held_out(fast, dynamic_->model);
  const EffectSeries without = held_out(fast, static_only_->model);
  const auto ramp_rms = [](const EffectSeries& effect, int channel) {
    double mean = 0.0;
    for (std::size_t w = 0; w < effect.truth.size(); ++w) mean += effect.truth[w][channel] - effect.removed[w][channel];
    mean /= effect.truth.size();
    double square = 0.0;
    int count = 0;
    for (std::size_t w = 0; w < effect.truth.size(); ++w) {
      if (std::abs(effect.rate_c_s[w]) < 0.01) continue;  // ramps: faster than 0.6 degC/min
      const double error = effect.truth[w][channel] - effect.removed[w][channel] - mean;
      square += error * error;
      ++count;
    }
    return std::sqrt(square / count);
  };
  for (int channel = 3; channel < 6; ++channel) {  // the accelerometers carry the dynamic-regime term
    const double dynamic = ramp_rms(with_rate, channel), static_only = ramp_rms(without, channel);
    std::printf("%-16s model error in ramps: %.3g static-only, %.3g with the rate term (%.1fx)\n", kChannel[channel],
                static_only, dynamic, static_only / dynamic);
    EXPECT_LT(dynamic, 0.5 * static_only) << kChannel[channel];
  }
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

}  // namespace
}  // namespace imu_lab
