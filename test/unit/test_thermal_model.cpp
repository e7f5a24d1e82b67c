// The thermal model itself: the correction formula, clamping, the temperature history (by
// stamp, never by arrival), the live compensator's ordering, and the YAML files.
#include <gtest/gtest.h>

#include <cmath>

#include <cstdio>
#include <fstream>
#include <random>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/thermal/thermal_compensator.h"
#include "imu_lab/thermal/thermal_model_yaml.h"

namespace imu_lab {
namespace {

thermal::ThermalModel example_model() {
  thermal::ThermalModel model;
  model.reference_temperature_c = 20.0;
  model.uses_temperature_rate = true;
  model.validity = {-20.0, 60.0, -0.05, 0.05, 0.0, 0.0};
  for (int axis = 0; axis < 3; ++axis) {
    model.gyro[axis].bias_polynomial = {1e-6 * (axis + 1), 2e-8};
    model.accelerometer[axis].bias_polynomial = {1e-3, -1e-5, 1e-7};
    model.accelerometer[axis].bias_per_temperature_rate = 0.05;
    model.accelerometer[axis].scale_factor_polynomial_ppm = {30.0, 0.1};
  }
  return model;
}

TEST(ThermalModel, CorrectsToTheReferenceTemperature) {
  const auto model = example_model();
  const thermal::ThermalInput input{45.0, 0.02, std::nullopt};
  const double dt = 25.0;
  const double bias = 1e-3 * dt - 1e-5 * dt * dt + 1e-7 * dt * dt * dt + 0.05 * 0.02;
  const double scale = 1e-6 * (30.0 * dt + 0.1 * dt * dt);
  const Eigen::Vector3d truth(0.1, -0.2, 9.8);
  const Eigen::Vector3d raw = truth * (1.0 + scale) + Eigen::Vector3d::Constant(bias);
  const auto corrected = thermal::correct(model, Eigen::Vector3d::Zero(), raw, input);
  EXPECT_FALSE(corrected.clamped);
  EXPECT_LT((corrected.specific_force_m_s2 - truth).norm(), 1e-12);
  EXPECT_NEAR(corrected.angular_rate_rad_s[1], -(2e-6 * dt + 2e-8 * dt * dt), 1e-15);
  // At the reference temperature, at rest: nothing changes.
  const auto unchanged = thermal::correct(model, Eigen::Vector3d::Ones(), raw, {20.0, 0.0, std::nullopt});
  EXPECT_EQ(unchanged.specific_force_m_s2, raw);
}

TEST(ThermalModel, ClampsOutsideTheTestedRangeAndFlagsIt) {
  const auto model = example_model();
  const Eigen::Vector3d raw(0.0, 0.0, 9.8);
  const auto at_edge = thermal::correct(model, raw, raw, {60.0, 0.0, std::nullopt});
  const auto beyond = thermal::correct(model, raw, raw, {85.0, 0.0, std::nullopt});
  EXPECT_TRUE(beyond.clamped);
  EXPECT_FALSE(at_edge.clamped);
  EXPECT_EQ(beyond.specific_force_m_s2, at_edge.specific_force_m_s2);
  EXPECT_TRUE(thermal::correct(model, raw, raw, {20.0, 0.5, std::nullopt}).clamped);  // rate too
}

TEST(ThermalModel, TemperatureHistoryMatchesByStampAndEstimatesTheRate) {
  thermal::TemperatureHistory history;
  for (int i = 0; i <= 1000; ++i)
    EXPECT_TRUE(history.add(stamp_ns_from_seconds(100.0 + 0.1 * i), 10.0 + 0.01 * i));  // 0.1 degC/s
  EXPECT_FALSE(history.add(stamp_ns_from_seconds(150.0), 0.0));                         // out of order: refused
  EXPECT_NEAR(*history.temperature_at(stamp_ns_from_seconds(150.05), 1.0), 10.0 + 0.01 * 500.5, 1e-9);
  EXPECT_NEAR(history.rate_at(stamp_ns_from_seconds(180.0), 20.0), 0.1, 1e-9);
  EXPECT_NEAR(*history.temperature_at(stamp_ns_from_seconds(200.5), 1.0), 20.0,
              1e-12);  // held at the end within the age
  EXPECT_FALSE(history.temperature_at(stamp_ns_from_seconds(201.5), 1.0).has_value());  // stale
  EXPECT_EQ(history.rate_at(stamp_ns_from_seconds(100.05), 20.0), 0.0);                 // not enough history yet
}

// The node's compensator must give the same output whatever the interleaving of the topics.
TEST(ThermalModel, CompensatorOutputDoesNotDependOnArrivalOrder) {
  const auto model = example_model();
  std::vector<io::ImuRecord> readings;
  std::vector<std::pair<double, double>> temperatures;
  for (int i = 1; i <= 3000; ++i) {
    const double t = 0.01 * i;
    readings.push_back(
        io::make_imu_record(t, Eigen::Vector3d::Constant(0.001 * i), Eigen::Vector3d(0.0, 0.0, 9.8 + 1e-4 * i)));
    if (i % 5 == 0) temperatures.push_back({t, 20.0 + 0.5 * t});  // 20 Hz thermosensor
  }
  const auto run = [&](unsigned seed) {
    std::mt19937 random(seed);
    thermal::ThermalCompensator compensator(model, 1.0);
    std::vector<thermal::CompensatedSample> out;
    std::size_t imu = 0, temperature = 0;
    while (imu < readings.size() || temperature < temperatures.size()) {
      const bool take_imu = temperature == temperatures.size() || (imu < readings.size() && random() % 3 != 0);
      if (take_imu) {
        compensator.add_imu(readings[imu++], &out);
      } else {
        compensator.add_temperature(stamp_ns_from_seconds(temperatures[temperature].first),
                                    temperatures[temperature].second, &out);
        ++temperature;
      }
    }
    compensator.flush(&out);
    return out;
  };
  const auto first = run(1), second = run(2);
  ASSERT_EQ(first.size(), readings.size());
  ASSERT_EQ(second.size(), readings.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    ASSERT_EQ(first[i].corrected.stamp_ns, second[i].corrected.stamp_ns);
    ASSERT_EQ(first[i].corrected.specific_force_m_s2, second[i].corrected.specific_force_m_s2) << i;
    ASSERT_NE(first[i].status, thermal::CompensatedSample::Status::kStale) << i;
  }
}

TEST(ThermalModel, CompensatorReportsStaleTemperature) {
  thermal::ThermalCompensator compensator(example_model(), 0.5);
  std::vector<thermal::CompensatedSample> out;
  compensator.add_temperature(std::int64_t{0}, 25.0, &out);
  for (int i = 1; i <= 300; ++i)
    compensator.add_imu(io::make_imu_record(0.01 * i, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()), &out);
  compensator.flush(&out);
  ASSERT_EQ(out.size(), 300u);
  EXPECT_NE(out[10].status, thermal::CompensatedSample::Status::kStale);   // 0.11 s old: held
  EXPECT_EQ(out[100].status, thermal::CompensatedSample::Status::kStale);  // 1.01 s old
  EXPECT_EQ(out[100].corrected.specific_force_m_s2, Eigen::Vector3d::UnitZ());
}

// What the node would publish must be usable: NaN, Inf and finite values beyond +-1e100 (1e308
// passed and came out corrected) are refused, like a stamp that is not after the previous one.
TEST(ThermalModel, CompensatorRefusesUnusableSamples) {
  thermal::ThermalCompensator compensator(example_model(), 0.5);
  std::vector<thermal::CompensatedSample> out;
  compensator.add_temperature(std::int64_t{0}, 25.0, &out);
  EXPECT_TRUE(
      compensator.add_imu(io::make_imu_record(0.01, Eigen::Vector3d(1e100, 0.0, 0.0), Eigen::Vector3d::UnitZ()), &out));
  EXPECT_FALSE(
      compensator.add_imu(io::make_imu_record(0.02, Eigen::Vector3d(1e308, 0.0, 0.0), Eigen::Vector3d::UnitZ()), &out));
  EXPECT_FALSE(
      compensator.add_imu(io::make_imu_record(0.03, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, -1e300, 9.8)), &out));
  EXPECT_FALSE(compensator.add_imu(
      io::make_imu_record(0.04, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, std::nan(""), 9.8)), &out));
  EXPECT_FALSE(compensator.add_imu(io::make_imu_record(0.01, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()), &out));
  EXPECT_TRUE(compensator.add_imu(io::make_imu_record(0.05, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()), &out));
  compensator.flush(&out);
  EXPECT_EQ(out.size(), 2u);
}

TEST(ThermalModel, YamlRoundTripAndStrictKeys) {
  const auto model = example_model();
  const std::string path = ::testing::TempDir() + "thermal_model_roundtrip.yaml";
  thermal::save_thermal_model(path, model, nullptr);
  const auto loaded = thermal::load_thermal_model(path);
  EXPECT_EQ(loaded.validity.temperature_max_c, 60.0);
  EXPECT_TRUE(loaded.uses_temperature_rate);
  EXPECT_EQ(loaded.accelerometer[2].bias_polynomial, model.accelerometer[2].bias_polynomial);
  EXPECT_EQ(loaded.accelerometer[1].scale_factor_polynomial_ppm, model.accelerometer[1].scale_factor_polynomial_ppm);
  EXPECT_EQ(loaded.gyro[2].bias_polynomial, model.gyro[2].bias_polynomial);

  const auto refused_key = [&](const std::string& from, const std::string& to) {
    std::string text = thermal::thermal_model_to_yaml(model, nullptr);
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    std::ofstream(path) << text;
    try {
      thermal::load_thermal_model(path);
    } catch (const ConfigError& error) {
      return error.key();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(refused_key("bias_polynomial_m_s2", "bias_polynom_m_s2"), "accelerometer.x.bias_polynom_m_s2");
  EXPECT_EQ(refused_key("temperature_max_c: 60", "temperature_max_c: -60"), "validity.temperature_max_c");
  EXPECT_EQ(refused_key("rate_window_s: 60", "rate_window_s: 0"), "rate_window_s");
  EXPECT_EQ(refused_key("format: imu_lab_thermal_model", "format: kalibr"), "format");
  std::remove(path.c_str());
}

}  // namespace
}  // namespace imu_lab
