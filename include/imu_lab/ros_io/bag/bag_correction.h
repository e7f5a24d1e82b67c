// Offline correction of a recorded bag with the live chain's stages: thermal compensation
// (thermal::ThermalCompensator, fed in bag order as rosbag play feeds thermal_compensator) then
// calibration (corrected_message, as calibration_corrector). Every corrected sample equals what
// the nodes publish for the same bag; every other message is copied unchanged.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "imu_lab/calib/imu_calibration.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/thermal/thermal_model.h"

namespace imu_lab {
namespace ros_io {

struct BagCorrectionOptions {
  std::string imu_topic;  // empty: the bag's only sensor_msgs/Imu topic
  std::string out_topic;  // empty: the IMU topic (replaced); another name keeps the raw topic too
  std::string temperature_topic = "/imu/temperature";
  std::string second_temperature_topic = "/imu/temperature2";  // read only if the model uses it
  double max_temperature_age_s = 1.0;                          // thermal_compensator's default
  std::optional<thermal::ThermalModel> thermal_model;
  std::optional<calib::ImuCalibration> calibration;
};

struct BagCorrectionSummary {
  std::string imu_topic, out_topic;
  std::size_t imu_messages = 0;
  std::size_t corrected = 0;
  std::size_t clamped = 0;  // outside the thermal model's validity range: corrected at its edge
  std::size_t stale = 0;    // no temperature within max_temperature_age_s: left out, as the node does
  std::size_t temperature_messages = 0;
  std::size_t copied_messages = 0;
  std::vector<std::string> copied_topics;
  // Copied topics that also carry the sensor's output (another sensor_msgs/Imu topic, the raw one
  // beside --out-topic, imu_lab/ImuIncrement): left as recorded, so worth a warning.
  std::vector<std::string> uncorrected_imu_topics;
};

// Writes out_bag_path atomically (nothing there on any failure). Throws InputError naming the bag
// and what to do: unreadable bag, missing or wrong topic, missing temperature for a thermal
// model, NaN/Inf or unordered IMU samples or temperatures, no sample corrected at all.
BagCorrectionSummary correct_bag(const BagRecording& recording, const std::string& out_bag_path,
                                 const BagCorrectionOptions& options);

}  // namespace ros_io
}  // namespace imu_lab
