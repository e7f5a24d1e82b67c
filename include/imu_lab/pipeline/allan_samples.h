// What the allan tool and the allan_monitor node feed the streaming Allan engine: one sample of
// six channels (gyro x, y, z, then accelerometer x, y, z) per message, from sensor_msgs/Imu rates
// or from imu_lab/ImuIncrement increments, with the message's header stamp.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "imu_lab/allan/streaming_options.h"
#include "imu_lab/io/imu_records.h"

namespace imu_lab {
namespace pipeline {

enum class AllanInput {
  kRate,       // sensor_msgs/Imu: angular velocity [rad/s], linear acceleration [m/s^2]
  kIncrement,  // imu_lab/ImuIncrement: delta angle [rad], delta velocity [m/s] per sample
};

// Accepts "rate" or "imu" (sensor_msgs/Imu) and "increment"; throws ConfigError naming `key`.
AllanInput parse_allan_input(const std::string& key, const std::string& value);
const char* allan_input_name(AllanInput input);      // "rate" or "increment"
const char* allan_input_datatype(AllanInput input);  // "sensor_msgs/Imu" or "imu_lab/ImuIncrement"
allan::InputKind engine_input_kind(AllanInput input);

constexpr std::size_t kAllanChannelCount = 6;
// Channel names and deviation units as they appear in CSV column names.
constexpr std::array<const char*, kAllanChannelCount> kAllanChannelNames = {"gyro_x",  "gyro_y",  "gyro_z",
                                                                            "accel_x", "accel_y", "accel_z"};
constexpr std::array<const char*, kAllanChannelCount> kAllanChannelUnits = {"rad_s", "rad_s", "rad_s",
                                                                            "m_s2",  "m_s2",  "m_s2"};
// The unit of one pushed value: a rate's (kAllanChannelUnits) or an increment's (rad, m_s).
const char* allan_value_unit(AllanInput input, std::size_t channel);

struct AllanSample {
  std::int64_t stamp_ns = 0;
  std::array<double, kAllanChannelCount> values{};
};

AllanSample to_allan_sample(const io::ImuRecord& record);
AllanSample to_allan_sample(const io::IncrementRecord& record);

}  // namespace pipeline
}  // namespace imu_lab
