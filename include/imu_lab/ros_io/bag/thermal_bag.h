// Reads a thermal-test bag into averaging windows: the thermosensor topic(s) first (they are
// small), then the IMU stream, each sample matched to the temperature at its own header stamp.
#pragma once

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
};

// Throws InputError: missing or empty temperature topic (naming what the bag has and what to
// do), stale temperature, unordered stamps, unreadable bag.
ThermalBagWindows read_thermal_windows(const BagRecording& recording, const ThermalBagTopics& topics,
                                       const thermal::WindowSettings& settings);

}  // namespace ros_io
}  // namespace imu_lab
