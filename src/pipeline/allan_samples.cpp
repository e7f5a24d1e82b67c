#include "imu_lab/pipeline/allan_samples.h"

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace pipeline {
namespace {

AllanSample make_sample(std::int64_t stamp_ns, const Eigen::Vector3d& gyro, const Eigen::Vector3d& accel) {
  AllanSample sample;
  sample.stamp_ns = stamp_ns;
  for (int axis = 0; axis < 3; ++axis) {
    sample.values[axis] = gyro[axis];
    sample.values[axis + 3] = accel[axis];
  }
  return sample;
}

}  // namespace

AllanInput parse_allan_input(const std::string& key, const std::string& value) {
  if (value == "rate" || value == "imu") return AllanInput::kRate;
  if (value == "increment") return AllanInput::kIncrement;
  throw ConfigError("allan input", key,
                    "is '" + value + "'; use rate (or imu: sensor_msgs/Imu) or increment (imu_lab/ImuIncrement)");
}

const char* allan_input_name(AllanInput input) { return input == AllanInput::kRate ? "rate" : "increment"; }

const char* allan_input_datatype(AllanInput input) {
  return input == AllanInput::kRate ? "sensor_msgs/Imu" : "imu_lab/ImuIncrement";
}

allan::InputKind engine_input_kind(AllanInput input) {
  return input == AllanInput::kRate ? allan::InputKind::kFrequency : allan::InputKind::kIncrement;
}

const char* allan_value_unit(AllanInput input, std::size_t channel) {
  if (input == AllanInput::kRate) return kAllanChannelUnits.at(channel);
  return channel < 3 ? "rad" : "m_s";
}

AllanSample to_allan_sample(const io::ImuRecord& record) {
  return make_sample(record.stamp_ns, record.angular_rate_rad_s, record.specific_force_m_s2);
}

AllanSample to_allan_sample(const io::IncrementRecord& record) {
  return make_sample(record.stamp_ns, record.delta_angle_rad, record.delta_velocity_m_s);
}

}  // namespace pipeline
}  // namespace imu_lab
