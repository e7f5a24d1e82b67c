// What the thermal fit refuses, and that each refusal says what to do.
#include <gtest/gtest.h>

#include <cmath>

#include "imu_lab/common/config_error.h"
#include "imu_lab/thermal/thermal_fit.h"

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

const std::vector<Eigen::Vector3d> kSixPositions = {Eigen::Vector3d::UnitX(),  -Eigen::Vector3d::UnitX(),
                                                    Eigen::Vector3d::UnitY(),  -Eigen::Vector3d::UnitY(),
                                                    Eigen::Vector3d::UnitZ(),  -Eigen::Vector3d::UnitZ()};

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
  for (int i = 0; i <= 100; ++i) history.add(1000.0 + i, 20.0);
  thermal::WindowSettings settings;
  settings.max_temperature_age_s = 2.0;
  thermal::ThermalWindowAverager averager(settings, history, nullptr);
  averager.add({1050.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()});
  try {
    averager.add({1105.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()});
    FAIL() << "a sample 5 s after the last temperature reading was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("temperature is stale"), std::string::npos) << message;
    EXPECT_NE(message.find("5.000 s away"), std::string::npos) << message;
    EXPECT_NE(message.find("maximum age 2.000 s"), std::string::npos) << message;
  }
  const thermal::TemperatureHistory empty;
  thermal::ThermalWindowAverager without(settings, empty, nullptr);
  EXPECT_THROW(without.add({1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()}), InputError);
}

}  // namespace
}  // namespace imu_lab
