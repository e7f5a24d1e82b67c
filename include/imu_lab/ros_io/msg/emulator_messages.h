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
EmulatorMessages to_messages(const emulator::EmulatedSample& sample, const ros::Time& stamp, double interval_s,
                             const std::string& frame_id);

// Header stamp of the n-th sample (n counts from 1; the stamp is the end of the interval), in
// whole nanoseconds from the start time: a double near 1e9 s resolves only ~0.1 us, which would
// show as false jitter in every stamp-based tau0 and gap check downstream.
ros::Time sample_stamp(double start_time_s, double interval_s, std::uint64_t n);

}  // namespace ros_io
}  // namespace imu_lab
