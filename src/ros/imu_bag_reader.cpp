#include "imu_lab/ros/imu_bag_reader.h"

#include <imu_lab/ImuIncrement.h>
#include <imu_lab/ImuTruth.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <limits>
#include <map>

#include "imu_lab/common/config_error.h"
#include "imu_wire_fields.h"

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

Eigen::Vector3d to_eigen(const geometry_msgs::Vector3& vector) { return {vector.x, vector.y, vector.z}; }

// covariance[0] == -1: the triad carries no data (sensor_msgs/Imu); its values become NaN.
ImuRecord make_imu_record(const ros::Time& stamp, const geometry_msgs::Vector3& angular_velocity,
                          double angular_velocity_covariance_0, const geometry_msgs::Vector3& linear_acceleration,
                          double linear_acceleration_covariance_0) {
  constexpr double kNoData = -1.0;
  const Eigen::Vector3d missing = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  ImuRecord record;
  record.stamp_s = stamp.toSec();
  record.stamp_ns = static_cast<std::int64_t>(stamp.toNSec());
  record.has_angular_rate = angular_velocity_covariance_0 != kNoData;
  record.has_specific_force = linear_acceleration_covariance_0 != kNoData;
  record.angular_rate_rad_s = record.has_angular_rate ? to_eigen(angular_velocity) : missing;
  record.specific_force_m_s2 = record.has_specific_force ? to_eigen(linear_acceleration) : missing;
  return record;
}

// Streams one topic's messages of type Message in bag order; every reader reports a wrong type,
// a truncated or a corrupt bag the same way.
template <class Message>
std::size_t for_each_message(rosbag::Bag& bag, const std::string& bag_path, const std::string& topic,
                             const std::string& datatype, const std::function<void(const Message&)>& on_message) {
  std::size_t count = 0;
  try {
    rosbag::View view(bag, rosbag::TopicQuery(topic));
    for (const rosbag::MessageInstance& instance : view) {
      const boost::shared_ptr<const Message> message = instance.template instantiate<Message>();
      if (!message) {
        throw InputError("bag " + bag_path + ": topic " + topic + " carries " + instance.getDataType() + ", not " +
                         datatype);
      }
      on_message(*message);
      ++count;
    }
  } catch (const rosbag::BagException& error) {
    throw InputError("bag " + bag_path + " is damaged after " + std::to_string(count) + " messages of " + topic +
                     ": " + error.what());
  } catch (const ros::Exception& error) {
    throw InputError("bag " + bag_path + " is damaged after " + std::to_string(count) + " messages of " + topic +
                     ": " + error.what());
  }
  return count;
}

template <class Message>
std::size_t for_each_message(const std::string& bag_path, const std::string& topic, const std::string& datatype,
                             const std::function<void(const Message&)>& on_message) {
  rosbag::Bag bag;
  open_for_reading(bag, bag_path);
  return for_each_message(bag, bag_path, topic, datatype, on_message);
}

}  // namespace

ImuRecord to_imu_record(const sensor_msgs::Imu& message) {
  return make_imu_record(message.header.stamp, message.angular_velocity, message.angular_velocity_covariance[0],
                         message.linear_acceleration, message.linear_acceleration_covariance[0]);
}

IncrementRecord to_increment_record(const imu_lab::ImuIncrement& message) {
  IncrementRecord record;
  record.stamp_ns = static_cast<std::int64_t>(message.header.stamp.toNSec());
  record.interval_s = message.interval_s;
  record.delta_angle_rad = to_eigen(message.delta_angle_rad);
  record.delta_velocity_m_s = to_eigen(message.delta_velocity_m_s);
  return record;
}

OpenBag::OpenBag(const std::string& bag_path) : path_(bag_path), bag_(std::make_unique<rosbag::Bag>()) {
  open_for_reading(*bag_, bag_path);
}

OpenBag::~OpenBag() = default;

std::vector<TopicInfo> OpenBag::topics() const {
  std::map<std::string, TopicInfo> by_name;
  try {
    rosbag::View view(*bag_);
    for (const rosbag::ConnectionInfo* connection : view.getConnections()) {
      TopicInfo& info = by_name[connection->topic];
      info.name = connection->topic;
      info.datatype = connection->datatype;
    }
    for (auto& entry : by_name) {
      rosbag::View topic_view(*bag_, rosbag::TopicQuery(entry.first));
      entry.second.message_count = topic_view.size();
    }
  } catch (const rosbag::BagException& error) {
    throw InputError("cannot read bag " + path_ + ": " + error.what());
  }
  std::vector<TopicInfo> topics;
  for (auto& entry : by_name) topics.push_back(entry.second);
  return topics;
}

TopicInfo OpenBag::choose_topic(const std::string& requested, const std::string& datatype) const {
  const std::vector<TopicInfo> topics = this->topics();
  if (!requested.empty()) {
    for (const auto& topic : topics) {
      if (topic.name != requested) continue;
      if (topic.datatype != datatype) {
        throw InputError("bag " + path_ + ": topic " + requested + " carries " + topic.datatype +
                         ", not " + datatype + "; topics in the bag:" + describe(topics));
      }
      return topic;
    }
    throw InputError("bag " + path_ + " has no topic " + requested + "; topics in the bag:" + describe(topics));
  }
  std::vector<TopicInfo> candidates;
  for (const auto& topic : topics) {
    if (topic.datatype == datatype) candidates.push_back(topic);
  }
  if (candidates.size() == 1) return candidates.front();
  if (candidates.empty()) {
    throw InputError("bag " + path_ + " has no " + datatype + " topic; topics in the bag:" + describe(topics));
  }
  throw InputError("bag " + path_ + " has several " + datatype + " topics; choose one with --topic:" +
                   describe(candidates));
}

std::size_t OpenBag::for_each_imu(const std::string& topic, const std::function<void(const ImuRecord&)>& on_record) {
  return for_each_message<ImuWireFields>(*bag_, path_, topic, kImuType, [&](const ImuWireFields& message) {
    on_record(make_imu_record(message.stamp, message.angular_velocity, message.angular_velocity_covariance_0,
                              message.linear_acceleration, message.linear_acceleration_covariance_0));
  });
}

std::size_t OpenBag::for_each_increment(const std::string& topic,
                                        const std::function<void(const IncrementRecord&)>& on_record) {
  return for_each_message<imu_lab::ImuIncrement>(
      *bag_, path_, topic, "imu_lab/ImuIncrement",
      [&](const imu_lab::ImuIncrement& message) { on_record(to_increment_record(message)); });
}

std::size_t OpenBag::for_each_message_in_order(const std::function<void(const rosbag::MessageInstance&)>& on_message) {
  std::size_t count = 0;
  try {
    rosbag::View view(*bag_);
    for (const rosbag::MessageInstance& instance : view) {
      on_message(instance);
      ++count;
    }
  } catch (const rosbag::BagException& error) {
    throw InputError("bag " + path_ + " is damaged after " + std::to_string(count) + " messages: " + error.what());
  } catch (const ros::Exception& error) {
    throw InputError("bag " + path_ + " is damaged after " + std::to_string(count) + " messages: " + error.what());
  }
  return count;
}

std::vector<TopicInfo> list_topics(const std::string& bag_path) { return OpenBag(bag_path).topics(); }

std::string choose_imu_topic(const std::string& bag_path, const std::string& requested) {
  return choose_topic(bag_path, requested, kImuType);
}

std::string choose_topic(const std::string& bag_path, const std::string& requested, const std::string& datatype) {
  return OpenBag(bag_path).choose_topic(requested, datatype).name;
}

std::size_t for_each_imu(const std::string& bag_path, const std::string& topic,
                         const std::function<void(const ImuRecord&)>& on_record) {
  return OpenBag(bag_path).for_each_imu(topic, on_record);
}

std::size_t for_each_increment(const std::string& bag_path, const std::string& topic,
                               const std::function<void(const IncrementRecord&)>& on_record) {
  return OpenBag(bag_path).for_each_increment(topic, on_record);
}

std::size_t for_each_truth(const std::string& bag_path, const std::string& topic,
                           const std::function<void(const TruthRecord&)>& on_record) {
  return for_each_message<imu_lab::ImuTruth>(bag_path, topic, "imu_lab/ImuTruth", [&](const imu_lab::ImuTruth& message) {
    TruthRecord record;
    record.stamp_ns = static_cast<std::int64_t>(message.header.stamp.toNSec());
    record.q_body_to_enu = Eigen::Quaterniond(message.orientation.w, message.orientation.x, message.orientation.y,
                                              message.orientation.z);
    record.angular_rate_rad_s = to_eigen(message.angular_velocity_rad_s);
    record.specific_force_m_s2 = to_eigen(message.specific_force_m_s2);
    record.latitude_rad = message.latitude_rad;
    record.longitude_rad = message.longitude_rad;
    record.height_m = message.height_m;
    record.velocity_enu_m_s = to_eigen(message.velocity_enu_m_s);
    on_record(record);
  });
}

std::size_t for_each_temperature(const std::string& bag_path, const std::string& topic,
                                 const std::function<void(const TemperatureRecord&)>& on_record) {
  return for_each_message<sensor_msgs::Temperature>(
      bag_path, topic, "sensor_msgs/Temperature", [&](const sensor_msgs::Temperature& message) {
        on_record({message.header.stamp.toSec(), message.temperature});
      });
}

}  // namespace ros_io
}  // namespace imu_lab
