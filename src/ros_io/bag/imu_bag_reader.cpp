#include "imu_lab/ros_io/bag/imu_bag_reader.h"

#include <imu_lab/ImuIncrement.h>
#include <imu_lab/ImuTruth.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/ros_io/msg/emulator_messages.h"
#include "imu_lab/ros_io/msg/vector_message.h"
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

// covariance[0] == -1: the triad carries no data (sensor_msgs/Imu); its values become NaN.
ImuRecord make_imu_record(const ros::Time& stamp, const geometry_msgs::Vector3& angular_velocity,
                          double angular_velocity_covariance_0, const geometry_msgs::Vector3& linear_acceleration,
                          double linear_acceleration_covariance_0) {
  constexpr double kNoData = -1.0;
  const Eigen::Vector3d missing = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  ImuRecord record;
  record.stamp_ns = static_cast<std::int64_t>(stamp.toNSec());
  record.has_angular_rate = angular_velocity_covariance_0 != kNoData;
  record.has_specific_force = linear_acceleration_covariance_0 != kNoData;
  record.angular_rate_rad_s = record.has_angular_rate ? eigen_from_message(angular_velocity) : missing;
  record.specific_force_m_s2 = record.has_specific_force ? eigen_from_message(linear_acceleration) : missing;
  return record;
}

std::int64_t stamp_ns_of(const ImuWireFields& message) { return static_cast<std::int64_t>(message.stamp.toNSec()); }
template <class Message>
std::int64_t stamp_ns_of(const Message& message) {
  return static_cast<std::int64_t>(message.header.stamp.toNSec());
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
  record.delta_angle_rad = eigen_from_message(message.delta_angle_rad);
  record.delta_velocity_m_s = eigen_from_message(message.delta_velocity_m_s);
  return record;
}

std::string BagRecording::name() const {
  if (paths.size() == 1) return paths.front();
  if (paths.empty()) return "(no bag)";
  return paths.front() + " (+ " + std::to_string(paths.size() - 1) + " split files)";
}

struct OpenBag::File {
  std::string path;
  rosbag::Bag bag;
  ros::Time begin, end;  // receive times of the first and last message (any topic)
  bool empty = true;
};

OpenBag::OpenBag(const BagRecording& recording)
    : path_(recording.name()), window_(recording.window), on_progress_(recording.on_progress) {
  if (recording.paths.empty()) throw InputError("no bag given");
  const std::string window_problem = time_window_problem(window_);
  if (!window_problem.empty()) throw ConfigError("recording " + path_, "time window", window_problem);
  for (const std::string& path : recording.paths) {
    auto file = std::make_unique<File>();
    file->path = path;
    open_for_reading(file->bag, path);
    try {
      rosbag::View view(file->bag);
      file->empty = view.size() == 0;
      if (!file->empty) {
        file->begin = view.getBeginTime();
        file->end = view.getEndTime();
      }
    } catch (const rosbag::BagException& error) {
      throw InputError("cannot read bag " + path + ": " + error.what());
    }
    files_.push_back(std::move(file));
  }
  // rosbag record --split starts a file where the previous one ended: order by recording time,
  // which also puts "_10.bag" after "_9.bag" whatever order the shell listed them in.
  std::stable_sort(files_.begin(), files_.end(), [](const auto& a, const auto& b) {
    if (a->empty != b->empty) return b->empty;
    return a->begin < b->begin;
  });
  for (std::size_t k = 1; k < files_.size(); ++k) {
    const File& before = *files_[k - 1];
    const File& after = *files_[k];
    if (before.empty || after.empty) continue;
    if (after.path == before.path) throw InputError("bag " + after.path + " is named twice in one recording");
    if (after.begin <= before.end) {
      throw InputError("bags " + before.path + " and " + after.path + " overlap in recording time (" + before.path +
                       " ends at " + format_stamp_s(static_cast<std::int64_t>(before.end.toNSec())) + " s, " +
                       after.path + " starts at " + format_stamp_s(static_cast<std::int64_t>(after.begin.toNSec())) +
                       " s" + "): they are not the split files of one recording");
    }
  }
}

OpenBag::~OpenBag() = default;

std::vector<std::string> OpenBag::ordered_paths() const {
  std::vector<std::string> paths;
  for (const auto& file : files_) paths.push_back(file->path);
  return paths;
}

// Streams one topic's messages of type Message in stamp order across the files, inside the
// window; every reader reports a wrong type, a truncated or a corrupt bag, and files that do
// not follow on, the same way.
template <class Message>
std::size_t OpenBag::stream(const std::string& topic, const std::string& datatype,
                            const std::function<void(const Message&)>& on_message) {
  joins_.clear();
  std::size_t read = 0, handed = 0;
  std::optional<std::int64_t> first_stamp_ns, last_stamp_ns;
  std::string last_path;
  std::int64_t window_begin_ns = 0, window_end_ns = 0;
  const bool whole = window_.is_whole();
  const std::size_t total = on_progress_ ? count_in_files(topic) : 0;
  for (const auto& file : files_) {
    std::size_t read_in_file = 0;
    try {
      rosbag::View view(file->bag, rosbag::TopicQuery(topic));
      for (const rosbag::MessageInstance& instance : view) {
        const boost::shared_ptr<const Message> message = instance.template instantiate<Message>();
        if (!message) {
          throw InputError("bag " + file->path + ": topic " + topic + " carries " + instance.getDataType() + ", not " +
                           datatype);
        }
        const std::int64_t stamp_ns = stamp_ns_of(*message);
        if (read_in_file == 0 && last_stamp_ns) {
          if (stamp_ns <= *last_stamp_ns) {
            throw InputError("bags " + last_path + " and " + file->path + " are out of order on " + topic + ": " +
                             last_path + "'s last stamp " + format_stamp_s(*last_stamp_ns) + " s is not before " +
                             file->path + "'s first " + format_stamp_s(stamp_ns) + " s" +
                             " (overlapping files, or files of different recordings)");
          }
          joins_.push_back({last_path, file->path, (stamp_ns - *last_stamp_ns) * 1e-9});
        }
        if (!first_stamp_ns) {
          first_stamp_ns = stamp_ns;
          window_begin_ns = stamp_ns + stamp_ns_from_seconds(window_.start_s);
          window_end_ns = std::isinf(window_.end_s) ? std::numeric_limits<std::int64_t>::max()
                                                    : stamp_ns + stamp_ns_from_seconds(window_.end_s);
        }
        ++read;
        ++read_in_file;
        if (on_progress_) on_progress_(read, total);
        last_stamp_ns = stamp_ns;
        if (!whole && (stamp_ns < window_begin_ns || stamp_ns > window_end_ns)) continue;
        on_message(*message);
        ++handed;
      }
    } catch (const rosbag::BagException& error) {
      throw InputError("bag " + file->path + " is damaged after " + std::to_string(read) + " messages of " + topic +
                       ": " + error.what());
    } catch (const ros::Exception& error) {
      throw InputError("bag " + file->path + " is damaged after " + std::to_string(read) + " messages of " + topic +
                       ": " + error.what());
    }
    if (read_in_file > 0) last_path = file->path;
  }
  return handed;
}

std::vector<TopicInfo> OpenBag::topics() const {
  std::map<std::string, TopicInfo> by_name;
  try {
    for (const auto& file : files_) {
      rosbag::View view(file->bag);
      for (const rosbag::ConnectionInfo* connection : view.getConnections()) {
        const bool known = by_name.count(connection->topic) > 0;
        TopicInfo& info = by_name[connection->topic];
        if (known && info.datatype != connection->datatype) {
          throw InputError("bag " + file->path + ": topic " + connection->topic + " carries " + connection->datatype +
                           " but " + info.datatype + " in another file of the recording " + path_);
        }
        info.name = connection->topic;
        info.datatype = connection->datatype;
      }
    }
    for (auto& entry : by_name) {
      for (const auto& file : files_) {
        rosbag::View topic_view(file->bag, rosbag::TopicQuery(entry.first));
        entry.second.message_count += topic_view.size();
      }
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
        throw InputError("bag " + path_ + ": topic " + requested + " carries " + topic.datatype + ", not " + datatype +
                         "; topics in the bag:" + describe(topics));
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
  throw InputError("bag " + path_ + " has several " + datatype +
                   " topics; choose one with --topic:" + describe(candidates));
}

std::size_t OpenBag::for_each_imu(const std::string& topic, const std::function<void(const ImuRecord&)>& on_record) {
  return stream<ImuWireFields>(topic, kImuType, [&](const ImuWireFields& message) {
    on_record(make_imu_record(message.stamp, message.angular_velocity, message.angular_velocity_covariance_0,
                              message.linear_acceleration, message.linear_acceleration_covariance_0));
  });
}

std::size_t OpenBag::for_each_increment(const std::string& topic,
                                        const std::function<void(const IncrementRecord&)>& on_record) {
  return stream<imu_lab::ImuIncrement>(topic, "imu_lab/ImuIncrement", [&](const imu_lab::ImuIncrement& message) {
    on_record(to_increment_record(message));
  });
}

std::size_t OpenBag::for_each_truth(const std::string& topic,
                                    const std::function<void(const TruthRecord&)>& on_record) {
  return stream<imu_lab::ImuTruth>(topic, "imu_lab/ImuTruth",
                                   [&](const imu_lab::ImuTruth& message) { on_record(to_truth_record(message)); });
}

std::size_t OpenBag::for_each_temperature(const std::string& topic,
                                          const std::function<void(const TemperatureRecord&)>& on_record) {
  return stream<sensor_msgs::Temperature>(
      topic, "sensor_msgs/Temperature", [&](const sensor_msgs::Temperature& message) {
        on_record({static_cast<std::int64_t>(message.header.stamp.toNSec()), message.temperature});
      });
}

std::size_t OpenBag::count_in_files(const std::string& topic) const {
  std::size_t count = 0;
  for (const auto& file : files_) {
    try {
      count +=
          topic.empty() ? rosbag::View(file->bag).size() : rosbag::View(file->bag, rosbag::TopicQuery(topic)).size();
    } catch (const rosbag::BagException&) {
      // Only for the progress line: the pass itself reports the damage.
    }
  }
  return count;
}

std::size_t OpenBag::for_each_message_in_order(const std::function<void(const rosbag::MessageInstance&)>& on_message) {
  std::size_t count = 0;
  const std::size_t total = on_progress_ ? count_in_files("") : 0;
  for (const auto& file : files_) {
    try {
      rosbag::View view(file->bag);
      for (const rosbag::MessageInstance& instance : view) {
        on_message(instance);
        ++count;
        if (on_progress_) on_progress_(count, total);
      }
    } catch (const rosbag::BagException& error) {
      throw InputError("bag " + file->path + " is damaged after " + std::to_string(count) +
                       " messages: " + error.what());
    } catch (const ros::Exception& error) {
      throw InputError("bag " + file->path + " is damaged after " + std::to_string(count) +
                       " messages: " + error.what());
    }
  }
  return count;
}

std::vector<TopicInfo> list_topics(const BagRecording& recording) { return OpenBag(recording).topics(); }

std::string choose_imu_topic(const BagRecording& recording, const std::string& requested) {
  return choose_topic(recording, requested, kImuType);
}

std::string choose_topic(const BagRecording& recording, const std::string& requested, const std::string& datatype) {
  return OpenBag(recording).choose_topic(requested, datatype).name;
}

std::size_t for_each_imu(const BagRecording& recording, const std::string& topic,
                         const std::function<void(const ImuRecord&)>& on_record) {
  return OpenBag(recording).for_each_imu(topic, on_record);
}

std::size_t for_each_increment(const BagRecording& recording, const std::string& topic,
                               const std::function<void(const IncrementRecord&)>& on_record) {
  return OpenBag(recording).for_each_increment(topic, on_record);
}

std::size_t for_each_truth(const BagRecording& recording, const std::string& topic,
                           const std::function<void(const TruthRecord&)>& on_record) {
  return OpenBag(recording).for_each_truth(topic, on_record);
}

std::size_t for_each_temperature(const BagRecording& recording, const std::string& topic,
                                 const std::function<void(const TemperatureRecord&)>& on_record) {
  return OpenBag(recording).for_each_temperature(topic, on_record);
}

}  // namespace ros_io
}  // namespace imu_lab
