#include "imu_lab/ros/imu_bag_reader.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>

#include <map>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace ros_io {
namespace {

const char* const kImuType = "sensor_msgs/Imu";

void open_for_reading(rosbag::Bag& bag, const std::string& bag_path) {
  try {
    bag.open(bag_path, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& error) {
    throw InputError("cannot read bag " + bag_path + ": " + error.what() +
                     " (is it a complete ROS 1 bag? a bag cut short by a crash can be repaired with "
                     "`rosbag reindex`)");
  }
}

std::string describe(const std::vector<TopicInfo>& topics) {
  std::string text;
  for (const auto& topic : topics) {
    text += "\n  " + topic.name + " (" + topic.datatype + ", " + std::to_string(topic.message_count) + " messages)";
  }
  return text.empty() ? " (none)" : text;
}

}  // namespace

std::vector<TopicInfo> list_topics(const std::string& bag_path) {
  rosbag::Bag bag;
  open_for_reading(bag, bag_path);
  std::map<std::string, TopicInfo> by_name;
  try {
    rosbag::View view(bag);
    for (const rosbag::ConnectionInfo* connection : view.getConnections()) {
      TopicInfo& info = by_name[connection->topic];
      info.name = connection->topic;
      info.datatype = connection->datatype;
    }
    for (auto& entry : by_name) {
      rosbag::View topic_view(bag, rosbag::TopicQuery(entry.first));
      entry.second.message_count = topic_view.size();
    }
  } catch (const rosbag::BagException& error) {
    throw InputError("cannot read bag " + bag_path + ": " + error.what());
  }
  std::vector<TopicInfo> topics;
  for (auto& entry : by_name) topics.push_back(entry.second);
  return topics;
}

std::string choose_imu_topic(const std::string& bag_path, const std::string& requested) {
  const std::vector<TopicInfo> topics = list_topics(bag_path);
  if (!requested.empty()) {
    for (const auto& topic : topics) {
      if (topic.name != requested) continue;
      if (topic.datatype != kImuType) {
        throw InputError("bag " + bag_path + ": topic " + requested + " carries " + topic.datatype +
                         ", not " + kImuType + "; topics in the bag:" + describe(topics));
      }
      return requested;
    }
    throw InputError("bag " + bag_path + " has no topic " + requested + "; topics in the bag:" + describe(topics));
  }
  std::vector<TopicInfo> candidates;
  for (const auto& topic : topics) {
    if (topic.datatype == kImuType) candidates.push_back(topic);
  }
  if (candidates.size() == 1) return candidates.front().name;
  if (candidates.empty()) {
    throw InputError("bag " + bag_path + " has no " + kImuType + " topic; topics in the bag:" + describe(topics));
  }
  throw InputError("bag " + bag_path + " has several " + kImuType + " topics; choose one with --topic:" +
                   describe(candidates));
}

std::size_t for_each_imu(const std::string& bag_path, const std::string& topic,
                         const std::function<void(const ImuRecord&)>& on_record) {
  rosbag::Bag bag;
  open_for_reading(bag, bag_path);
  std::size_t count = 0;
  try {
    rosbag::View view(bag, rosbag::TopicQuery(topic));
    for (const rosbag::MessageInstance& instance : view) {
      const sensor_msgs::Imu::ConstPtr message = instance.instantiate<sensor_msgs::Imu>();
      if (!message) {
        throw InputError("bag " + bag_path + ": topic " + topic + " carries " + instance.getDataType() +
                         ", not " + kImuType);
      }
      ImuRecord record;
      record.stamp_s = message->header.stamp.toSec();
      record.angular_rate_rad_s << message->angular_velocity.x, message->angular_velocity.y,
          message->angular_velocity.z;
      record.specific_force_m_s2 << message->linear_acceleration.x, message->linear_acceleration.y,
          message->linear_acceleration.z;
      on_record(record);
      ++count;
    }
  } catch (const rosbag::BagException& error) {
    throw InputError("bag " + bag_path + " is damaged after " + std::to_string(count) + " messages of " +
                     topic + ": " + error.what());
  } catch (const ros::Exception& error) {
    throw InputError("bag " + bag_path + " is damaged after " + std::to_string(count) + " messages of " +
                     topic + ": " + error.what());
  }
  return count;
}

}  // namespace ros_io
}  // namespace imu_lab
