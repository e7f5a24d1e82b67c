// Conversion of emulator samples into the messages the emulator node publishes and the
// emulate tool writes: sensor_msgs/Imu (/imu/raw), sensor_msgs/Temperature (/imu/temperature),
// imu_lab/ImuTruth (/imu/truth) and imu_lab/ImuIncrement (/imu/increment); when the scenario
// has a second, lagging thermosensor, its sensor_msgs/Temperature on /imu/temperature2.
#pragma once

#include <imu_lab/ImuIncrement.h>
#include <imu_lab/ImuTruth.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <cstdint>
#include <optional>
#include <string>

#include "imu_lab/emulator/imu_emulator.h"

namespace imu_lab {
namespace ros_io {

// Default topic names (every node remaps cleanly).
struct EmulatorTopics {
  std::string raw = "/imu/raw";
  std::string temperature = "/imu/temperature";
  std::string second_temperature = "/imu/temperature2";
  std::string truth = "/imu/truth";
  std::string increment = "/imu/increment";
};

struct EmulatorMessages {
  sensor_msgs::Imu raw;
  sensor_msgs::Temperature temperature;
  std::optional<sensor_msgs::Temperature> second_temperature;  // only with a second thermosensor
  imu_lab::ImuTruth truth;
  imu_lab::ImuIncrement increment;
};

// `frame_id` names the sensor frame (REP-145). The Imu orientation is marked unknown
// (covariance[0] = -1): a raw IMU does not estimate attitude. Covariance diagonals are the
// profile's per-sample stationary noise variances.
// Every header carries the sample's integer stamp (emulator/imu_emulator.h).
EmulatorMessages to_messages(const emulator::EmulatedSample& sample, double interval_s, const std::string& frame_id);

// imu_lab/ImuTruth both ways (the message has no second temperature; read back it is empty).
imu_lab::ImuTruth to_truth_message(const io::TruthRecord& truth, const std_msgs::Header& header);
io::TruthRecord to_truth_record(const imu_lab::ImuTruth& message);

}  // namespace ros_io
}  // namespace imu_lab
