// Reads a thermal-test bag into averaging windows: the thermosensor topic(s) first (they are
// small), then the IMU stream, each sample matched to the temperature at its own header stamp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/thermal/thermal_windows.h"

namespace imu_lab {
namespace ros_io {

struct ThermalBagTopics {
  std::string imu;  // empty: the bag's only sensor_msgs/Imu topic
  std::string temperature = "/imu/temperature";
  std::string second_temperature;  // empty: none
};

struct ThermalBagWindows {
  std::vector<thermal::ThermalWindow> windows;
  std::string imu_topic;
  std::size_t imu_messages = 0;
  std::size_t temperature_messages = 0;
  // With the regime switch: the settings used (the threshold from the data when none was given)
  // and, then, how it was derived; the dynamic regime's share of the thermosensor readings.
  thermal::RegimeSwitchSettings regime_switch;
  std::optional<thermal::RegimeThresholdSuggestion> suggested_threshold;
  std::size_t readings_over_threshold = 0;
};

// Throws InputError: missing or empty temperature topic (naming what the bag has and what to
// do), stale temperature, unordered stamps, unreadable bag, a regime switch without a threshold
// on a temperature that never changes. `regime_switch` (enabled): each window gets the share of
// its samples in the dynamic regime; threshold_c_s2 0 = derive it from the thermosensor record.
ThermalBagWindows read_thermal_windows(const BagRecording& recording, const ThermalBagTopics& topics,
                                       const thermal::WindowSettings& settings,
                                       const thermal::RegimeSwitchSettings& regime_switch = {});

}  // namespace ros_io
}  // namespace imu_lab
