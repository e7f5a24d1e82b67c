// What the thermal fit refuses, and that each refusal says what to do.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/thermal/thermal_fit.h"
#include "imu_lab/thermal/thermal_model.h"

namespace imu_lab {
namespace {

using thermal::ThermalFitError;
using thermal::ThermalWindow;

// Static windows in the given orientations (up = gravity reaction in the body), temperatures
// from low to high, a linear bias of 1e-4 m/s^2 per degC and small alternating noise.
std::vector<ThermalWindow> synthetic_windows(const std::vector<Eigen::Vector3d>& ups, double low_c, double high_c,
                                             int per_orientation) {
  std::vector<ThermalWindow> windows;
  for (const Eigen::Vector3d& up : ups) {
    for (int i = 0; i < per_orientation; ++i) {
      ThermalWindow w;
      w.temperature_c = low_c + (high_c - low_c) * i / std::max(1, per_orientation - 1);
      w.mid_stamp_s = 60.0 * windows.size();
      const double noise = (i % 2 ? 1.0 : -1.0) * 1e-5;
      w.mean_specific_force_m_s2 = 9.8 * up + Eigen::Vector3d::Constant(1e-4 * (w.temperature_c - 20.0) + noise);
      w.mean_angular_rate_rad_s = Eigen::Vector3d::Constant(1e-7 * (w.temperature_c - 20.0) + noise * 1e-2);
      w.is_static = true;
      w.sample_count = 600;
      windows.push_back(w);
    }
  }
  return windows;
}

std::string refusal(const std::vector<ThermalWindow>& windows, const thermal::ThermalFitOptions& options) {
  try {
    thermal::fit_thermal_model(windows, 60.0, options);
  } catch (const ThermalFitError& error) {
    return error.what();
  }
  return "";
}

const std::vector<Eigen::Vector3d> kSixPositions = {Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(),
                                                    Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitY(),
                                                    Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()};

TEST(ThermalRefusals, SixPositionsOverAWideSpanFit) {
  thermal::ThermalFitOptions options;
  options.polynomial_order = 2;
  const auto result = thermal::fit_thermal_model(synthetic_windows(kSixPositions, -20.0, 60.0, 20), 60.0, options);
  EXPECT_EQ(result.orientations.clusters.size(), 6u);
  EXPECT_NEAR(result.model.accelerometer[0].bias_polynomial[0], 1e-4, 1e-6);
  EXPECT_NEAR(result.model.validity.temperature_min_c, -20.0, 1e-9);
  EXPECT_NEAR(result.model.validity.temperature_max_c, 60.0, 1e-9);
}

TEST(ThermalRefusals, TooSmallASpanForTheOrder) {
  thermal::ThermalFitOptions options;
  options.polynomial_order = 3;
  const std::string message = refusal(synthetic_windows(kSixPositions, 20.0, 30.0, 20), options);
  EXPECT_NE(message.find("order 3"), std::string::npos) << message;
  EXPECT_NE(message.find("span only 10.0 degC"), std::string::npos) << message;
  EXPECT_NE(message.find("wider range"), std::string::npos) << message;
  // Cross-validation takes the orders the span allows (here 1 and 2), no refusal.
  options.polynomial_order.reset();
  EXPECT_EQ(refusal(synthetic_windows(kSixPositions, 20.0, 30.0, 20), options), "");
  // ... but not below the first order's span.
  const std::string narrow = refusal(synthetic_windows(kSixPositions, 20.0, 22.0, 20), options);
  EXPECT_NE(narrow.find("span only 2.0 degC"), std::string::npos) << narrow;
}

TEST(ThermalRefusals, TooFewWindowsForTheParameters) {
  thermal::ThermalFitOptions options;
  options.polynomial_order = 4;
  const std::string message = refusal(synthetic_windows(kSixPositions, -20.0, 60.0, 3), options);
  EXPECT_NE(message.find("18 static windows"), std::string::npos) << message;
  EXPECT_NE(message.find("record a longer test"), std::string::npos) << message;
}

TEST(ThermalRefusals, ScaleFactorFromOneOrientation) {
  thermal::ThermalFitOptions options;
  const std::string message = refusal(synthetic_windows({Eigen::Vector3d::UnitZ()}, -20.0, 60.0, 40), options);
  EXPECT_NE(message.find("two opposite orientations"), std::string::npos) << message;
  EXPECT_NE(message.find("accelerometer z"), std::string::npos) << message;
  EXPECT_NE(message.find("cannot separate bias(T) from scale factor(T)"), std::string::npos) << message;
  EXPECT_NE(message.find("fit the bias only"), std::string::npos) << message;
  // Bias only: fine from one orientation.
  options.accelerometer_scale_factor = false;
  EXPECT_EQ(refusal(synthetic_windows({Eigen::Vector3d::UnitZ()}, -20.0, 60.0, 40), options), "");
}

TEST(ThermalRefusals, NoStaticWindowAndNoSecondSensor) {
  auto windows = synthetic_windows(kSixPositions, -20.0, 60.0, 10);
  thermal::ThermalFitOptions options;
  options.second_sensor_term = true;
  EXPECT_NE(refusal(windows, options).find("second thermosensor topic"), std::string::npos);
  for (auto& w : windows) w.is_static = false;
  EXPECT_NE(refusal(windows, thermal::ThermalFitOptions{}).find("no static window"), std::string::npos);
}

TEST(ThermalRefusals, StaleOrMissingTemperatureStopsTheAveraging) {
  thermal::TemperatureHistory history;
  for (int i = 0; i <= 100; ++i) history.add((1000 + i) * kNanosecondsPerSecond, 20.0);
  thermal::WindowSettings settings;
  settings.max_temperature_age_s = 2.0;
  thermal::ThermalWindowAverager averager(settings, history, nullptr);
  averager.add(io::make_imu_record(1050.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()));
  try {
    averager.add(io::make_imu_record(1105.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()));
    FAIL() << "a sample 5 s after the last temperature reading was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("temperature is stale"), std::string::npos) << message;
    EXPECT_NE(message.find("5.000 s away"), std::string::npos) << message;
    EXPECT_NE(message.find("maximum age 2.000 s"), std::string::npos) << message;
  }
  const thermal::TemperatureHistory empty;
  thermal::ThermalWindowAverager without(settings, empty, nullptr);
  EXPECT_THROW(without.add(io::make_imu_record(1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ())), InputError);
}

// Real stamps jitter: with +-30 % on every interval the smallest one is 0.7 of the period, and
// taking it for the period made every window "short of samples", so no window was static ("no
// window with the IMU at rest"). The median interval is the period; a window with a gap is still
// short.
TEST(ThermalWindows, JitteredStampsFillTheirWindowsAndAGapDoesNot) {
  thermal::TemperatureHistory history;
  for (int i = 0; i <= 700; ++i) history.add((1000 + i) * kNanosecondsPerSecond, 20.0);
  thermal::WindowSettings settings;
  thermal::ThermalWindowAverager averager(settings, history, nullptr);
  std::uint64_t state = 16;
  const auto uniform = [&] {  // a fixed sequence in [0, 1)
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  double stamp_s = 1000.0;
  while (stamp_s < 1600.0) {
    const bool in_gap = stamp_s > 1330.0 && stamp_s < 1345.0;  // 15 s missing in the sixth window
    if (!in_gap) averager.add(io::make_imu_record(stamp_s, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 9.8)));
    stamp_s += 0.1 * (1.0 + 0.6 * (uniform() - 0.5));  // 10 Hz, +-30 %
  }
  const auto windows = averager.finish();
  ASSERT_EQ(windows.size(), 10u);
  for (std::size_t w = 0; w < windows.size(); ++w) {
    EXPECT_EQ(windows[w].is_static, w != 5) << "window " << w << " with " << windows[w].sample_count << " samples";
  }
}

// A steady temperature's rate (0) belongs in the validity box, with a margin: a test whose static
// windows all saw the temperature rise left 0 outside, and a steady temperature was "clamped" to a
// rate the sensor never had (in the demo 24,554 of 120,000 samples got a correction not there).
TEST(ThermalValidity, RateZeroIsInsideTheBoxWithAMargin) {
  auto windows = synthetic_windows(kSixPositions, -20.0, 60.0, 20);
  for (std::size_t w = 0; w < windows.size(); ++w) windows[w].rate_c_s = 0.01 + 0.01 * static_cast<double>(w % 5) / 4.0;
  thermal::ThermalFitOptions options;
  options.polynomial_order = 1;
  options.temperature_rate_term = true;
  const auto result = thermal::fit_thermal_model(windows, 60.0, options);
  const auto& box = result.model.validity;
  EXPECT_NEAR(box.rate_max_c_s, 0.02 + 0.002, 1e-12);
  EXPECT_NEAR(box.rate_min_c_s, -0.002, 1e-12);
  bool clamped = false;
  thermal::clamp_to_validity(result.model, {20.0, 0.0, std::nullopt}, &clamped);
  EXPECT_FALSE(clamped) << "a steady temperature is outside the model's range";
  thermal::clamp_to_validity(result.model, {20.0, 0.05, std::nullopt}, &clamped);
  EXPECT_TRUE(clamped);
  EXPECT_EQ(thermal::validity_range_text(result.model), "-20 .. 60 degC, -0.002 .. 0.022 degC/s");
  options.temperature_rate_term = false;
  EXPECT_EQ(thermal::validity_range_text(thermal::fit_thermal_model(windows, 60.0, options).model), "-20 .. 60 degC")
      << "no rate term: no rate range that could clamp";
}

}  // namespace
}  // namespace imu_lab
