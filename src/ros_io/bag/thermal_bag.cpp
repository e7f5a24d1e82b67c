#include "imu_lab/ros_io/bag/thermal_bag.h"

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/ros_io/bag/strict_imu_reading.h"

namespace imu_lab {
namespace ros_io {
namespace {

// Every reading of a sensor_msgs/Temperature topic into a history; the topic must exist.
std::size_t read_temperatures(const BagRecording& recording, const std::string& topic, const char* role,
                              thermal::TemperatureHistory* history) {
  try {
    choose_topic(recording, topic, "sensor_msgs/Temperature");
  } catch (const InputError& error) {
    throw InputError(std::string(error.what()) + "\nA thermal fit needs the " + role +
                     " (sensor_msgs/Temperature, stamped like the IMU): record it with the IMU, or name its topic "
                     "with the temperature-topic option");
  }
  std::size_t refused = 0;
  const std::size_t count = for_each_temperature(recording, topic, [&](const TemperatureRecord& record) {
    if (!history->add(record.stamp_ns, record.temperature_c)) ++refused;
  });
  if (count == 0)
    throw InputError("bag " + recording.name() + ": topic " + topic + " has no messages; the " + role +
                     " was not recorded");
  if (refused > 0) {
    throw InputError("bag " + recording.name() + ": " + std::to_string(refused) + " of " + std::to_string(count) +
                     " readings on " + topic +
                     " are not finite or not in increasing header-stamp order; fix the recording");
  }
  return count;
}

}  // namespace

ThermalBagWindows read_thermal_windows(const BagRecording& recording, const ThermalBagTopics& topics,
                                       const thermal::WindowSettings& settings,
                                       const thermal::RegimeSwitchSettings& regime_switch) {
  ThermalBagWindows out;
  out.imu_topic = choose_imu_topic(recording, topics.imu);
  // The thermosensors are read whole: the window (relative to the IMU's first stamp) selects IMU
  // samples, each of which still needs the temperature at its own stamp.
  thermal::TemperatureHistory temperature, second_temperature;
  out.temperature_messages = read_temperatures(recording.whole(), topics.temperature, "thermosensor", &temperature);
  const bool with_second = !topics.second_temperature.empty();
  if (with_second)
    read_temperatures(recording.whole(), topics.second_temperature, "second thermosensor", &second_temperature);
  std::optional<thermal::RegimeIndicator> indicator;
  out.regime_switch = regime_switch;
  if (regime_switch.enabled) {
    if (out.regime_switch.threshold_c_s2 == 0.0) {
      out.suggested_threshold = thermal::suggest_regime_threshold(temperature, regime_switch.window_s);
      out.regime_switch.threshold_c_s2 = out.suggested_threshold->threshold_c_s2;
      if (!(out.regime_switch.threshold_c_s2 > 0.0)) {
        throw InputError("bag " + recording.name() + ": the temperature on " + topics.temperature +
                         " never changes its rate, so there is no dynamic regime to switch to and no threshold to "
                         "derive; fit without the regime switch");
      }
    }
    try {
      indicator.emplace(out.regime_switch);
    } catch (const std::invalid_argument& error) {
      throw ConfigError("fit_thermal", "regime switch", error.what());
    }
    indicator->update_all(temperature);
    out.readings_over_threshold = indicator->readings_over_threshold();
  }
  thermal::ThermalWindowAverager averager(settings, temperature, with_second ? &second_temperature : nullptr,
                                          indicator ? &*indicator : nullptr);
  out.imu_messages =
      for_each_imu_strictly(recording, out.imu_topic, [&](const ImuRecord& record) { averager.add(record); });
  out.windows = averager.finish();
  return out;
}

}  // namespace ros_io
}  // namespace imu_lab
