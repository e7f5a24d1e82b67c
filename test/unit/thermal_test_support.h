// Emulated thermal tests for the thermal tests: the emulator's samples, the thermosensor
// histories as a bag would carry them (interval-mean temperature at the sample's stamp), and the
// exact thermal effect the profile put into each sample (the oracle for the model error).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "imu_lab/common/stamps.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/thermal_profile.h"
#include "imu_lab/thermal/thermal_fit.h"
#include "imu_lab/thermal/thermal_regime.h"
#include "imu_lab/thermal/thermal_windows.h"

#ifndef IMU_LAB_CONFIG_DIR
#define IMU_LAB_CONFIG_DIR "config"
#endif
#ifndef IMU_LAB_TEST_DATA_DIR
#define IMU_LAB_TEST_DATA_DIR "test/data"
#endif

namespace imu_lab {
namespace thermal_test {

inline std::string sensor_path(const std::string& name) {
  return std::string(IMU_LAB_CONFIG_DIR) + "/sensors/" + name + ".yaml";
}
inline std::string shipped_scenario(const std::string& name) {
  return std::string(IMU_LAB_CONFIG_DIR) + "/scenarios/" + name + ".yaml";
}
inline std::string test_scenario(const std::string& name) {
  return std::string(IMU_LAB_TEST_DATA_DIR) + "/thermal/" + name + ".yaml";
}

struct ThermalRun {
  std::vector<io::ImuRecord> readings;
  thermal::TemperatureHistory temperature;
  thermal::TemperatureHistory second_temperature;
  // What the profile's temperature terms added to each sample (bias + scale factor * true input).
  std::vector<Eigen::Vector3d> true_gyro_effect_rad_s;
  std::vector<Eigen::Vector3d> true_accelerometer_effect_m_s2;
  double sample_interval_s = 0.0;
};

inline ThermalRun emulate_thermal_run(const emulator::SensorProfile& profile, const emulator::ScenarioConfig& scenario,
                                      std::uint64_t seed, double rate_hz) {
  emulator::EmulatorSettings settings;
  settings.rate_hz = rate_hz;
  settings.seed = seed;
  settings.start_time_s = 1.0e9;
  emulator::ImuEmulator imu(profile, scenario, settings);
  const emulator::ThermalProfile temperatures(*scenario.thermal);
  ThermalRun run;
  run.sample_interval_s = imu.sample_interval_s();
  const auto count = static_cast<std::size_t>(std::llround(scenario.duration_s / run.sample_interval_s));
  run.readings.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const emulator::EmulatedSample sample = imu.next();
    run.readings.push_back(emulator::to_imu_record(sample));
    run.temperature.add(sample.stamp_ns, sample.temperature_c);
    if (sample.second_temperature_c) run.second_temperature.add(sample.stamp_ns, *sample.second_temperature_c);
    const double dt = run.sample_interval_s;
    const double rate_c_s =
        (temperatures.sensor_temperature_c((k + 1) * dt) - temperatures.sensor_temperature_c(k * dt)) / dt;
    const auto effect = [&](const emulator::ThermalSensitivity& thermal, const Eigen::Vector3d& input) {
      const auto second_c = sample.second_temperature_c;
      return Eigen::Vector3d(
          thermal.bias(sample.temperature_c, rate_c_s, second_c) +
          1e-6 * thermal.scale_factor_ppm(sample.temperature_c, rate_c_s, second_c).cwiseProduct(input));
    };
    run.true_gyro_effect_rad_s.push_back(effect(profile.gyro.thermal, sample.truth.angular_rate_rad_s));
    run.true_accelerometer_effect_m_s2.push_back(
        effect(profile.accelerometer.thermal, sample.truth.specific_force_m_s2));
  }
  return run;
}

// `regime` (may be null): the indicator, already fed with run.temperature (update_all).
inline std::vector<thermal::ThermalWindow> windows_of(const ThermalRun& run, const thermal::WindowSettings& settings,
                                                      bool with_second_sensor,
                                                      const thermal::RegimeIndicator* regime = nullptr) {
  thermal::ThermalWindowAverager averager(settings, run.temperature,
                                          with_second_sensor ? &run.second_temperature : nullptr, regime);
  for (const auto& reading : run.readings) averager.add(reading);
  return averager.finish();
}

// Per window of the held-out run: the true thermal effect and what the model removes, as window
// means of (index 0..2 gyro x..z, 3..5 accelerometer x..z).
struct EffectSeries {
  std::vector<std::array<double, 6>> truth, removed;
  std::vector<double> rate_c_s;
  std::vector<bool> clamped;
  std::vector<double> dynamic_fraction;  // of the window's samples in the dynamic regime (regime-switch model)
};

inline EffectSeries model_effect(const ThermalRun& run, const thermal::ThermalModel& model, double window_s) {
  EffectSeries out;
  const std::int64_t start_ns = run.readings.front().stamp_ns;
  long current = -1;
  std::array<double, 6> truth{}, removed{};
  double rate_sum = 0.0, dynamic_count = 0.0;
  int count = 0;
  bool clamped = false;
  std::optional<thermal::RegimeIndicator> regime;
  if (model.regime_switch.enabled) {
    regime.emplace(model.regime_switch);
    regime->update_all(run.temperature);
  }
  const auto close = [&] {
    if (count == 0) return;
    for (int i = 0; i < 6; ++i) {
      truth[i] /= count;
      removed[i] /= count;
    }
    out.truth.push_back(truth);
    out.removed.push_back(removed);
    out.rate_c_s.push_back(rate_sum / count);
    out.clamped.push_back(clamped);
    out.dynamic_fraction.push_back(dynamic_count / count);
    truth.fill(0.0);
    removed.fill(0.0);
    rate_sum = dynamic_count = 0.0;
    count = 0;
    clamped = false;
  };
  for (std::size_t k = 0; k < run.readings.size(); ++k) {
    const auto& reading = run.readings[k];
    const long index = static_cast<long>(std::floor(seconds_between(start_ns, reading.stamp_ns) / window_s));
    if (index != current) {
      close();
      current = index;
    }
    thermal::ThermalInput input;
    input.temperature_c = *run.temperature.temperature_at(reading.stamp_ns, 1.0);
    input.rate_c_s = run.temperature.rate_at(reading.stamp_ns, model.rate_window_s);
    if (!run.second_temperature.empty())
      input.second_temperature_c = run.second_temperature.temperature_at(reading.stamp_ns, 1.0);
    input.dynamic_regime = regime && regime->dynamic_at(reading.stamp_ns);
    dynamic_count += input.dynamic_regime ? 1.0 : 0.0;
    const auto corrected = thermal::correct(model, reading.angular_rate_rad_s, reading.specific_force_m_s2, input);
    for (int i = 0; i < 3; ++i) {
      truth[i] += run.true_gyro_effect_rad_s[k][i];
      truth[3 + i] += run.true_accelerometer_effect_m_s2[k][i];
      removed[i] += reading.angular_rate_rad_s[i] - corrected.angular_rate_rad_s[i];
      removed[3 + i] += reading.specific_force_m_s2[i] - corrected.specific_force_m_s2[i];
    }
    rate_sum += input.rate_c_s;
    clamped = clamped || corrected.clamped;
    ++count;
  }
  close();
  return out;
}

inline double peak_to_peak(const std::vector<double>& values) {
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  return *high - *low;
}

}  // namespace thermal_test
}  // namespace imu_lab
