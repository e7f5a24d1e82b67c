// Streams sensor_msgs/Imu messages out of a bag without loading it whole. Shared by every
// offline tool, so each reports a missing topic, a wrong message type or a corrupt bag the
// same clear way (imu_lab::InputError naming the bag and what to do).
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace imu_lab {
namespace ros_io {

struct ImuRecord {
  double stamp_s = 0.0;  // header stamp, never the bag's receive time
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();
};

struct TopicInfo {
  std::string name;
  std::string datatype;
  std::size_t message_count = 0;
};

// All topics of a bag with their types and counts. Throws InputError if the bag cannot be read.
std::vector<TopicInfo> list_topics(const std::string& bag_path);

// The IMU topic to read: `requested` if given (checked to exist and to be sensor_msgs/Imu),
// otherwise the only sensor_msgs/Imu topic; several candidates or none -> InputError listing them.
std::string choose_imu_topic(const std::string& bag_path, const std::string& requested);

// Calls `on_record` for each message of `topic` in bag order. Returns the number of messages.
// A bag that ends early (truncated, unindexed) or whose chunks are corrupt -> InputError.
std::size_t for_each_imu(const std::string& bag_path, const std::string& topic,
                         const std::function<void(const ImuRecord&)>& on_record);

}  // namespace ros_io
}  // namespace imu_lab
