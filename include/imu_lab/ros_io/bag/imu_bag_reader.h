// Streams sensor_msgs/Imu messages out of a bag without loading it whole. Shared by every
// offline tool, so each reports a missing topic, a wrong message type or a corrupt bag the
// same clear way (imu_lab::InputError naming the bag and what to do).
//
// A recording may be one bag or the files `rosbag record --split` cut it into (BagRecording):
// the files are read one after the other in stamp order, whatever order they are named in, as
// one stream; the time between one file's last stamp and the next file's first is whatever the
// recorder lost there, which the consumers treat like any other gap in the stamps (the Allan
// engine's split-and-pool policy) and which is reported (OpenBag::joins). Files whose recording
// times overlap, or whose header stamps do not follow on across a join, are refused naming both
// files. See doc/recordings.md.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <imu_lab/ImuIncrement.h>
#include <sensor_msgs/Imu.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "imu_lab/common/progress.h"
#include "imu_lab/io/imu_records.h"
#include "imu_lab/io/recording_window.h"

namespace rosbag {
class Bag;
class MessageInstance;
}  // namespace rosbag

namespace imu_lab {
namespace ros_io {

// The record types are the core's (io/imu_records.h), so ROS-free code can take them.
using io::describe_joins;
using io::describe_time_window;
using io::FileJoin;
using io::ImuRecord;
using io::IncrementRecord;
using io::TemperatureRecord;
using io::time_window_problem;
using io::TimeWindow;
using io::TruthRecord;

struct TopicInfo {
  std::string name;
  std::string datatype;
  std::size_t message_count = 0;  // over every file of the recording, whatever the window
};

// One recording: a bag, or the split files of one (read in stamp order), and the window to read.
struct BagRecording {
  BagRecording(const std::string& path) : paths{path} {}  // NOLINT: a bag is a recording
  BagRecording(const char* path) : paths{path} {}         // NOLINT
  BagRecording(std::vector<std::string> file_paths, TimeWindow time_window = TimeWindow())
      : paths(std::move(file_paths)), window(time_window) {}
  std::vector<std::string> paths;
  TimeWindow window;
  // Told (messages read, messages in the pass) as each for_each_* call reads, for a tool's
  // terminal progress (common/progress.h); empty: nothing told.
  ProgressCallback on_progress;
  // How messages name the recording: the path, or "a.bag (+ 2 split files)".
  std::string name() const;
  // The same files without the window.
  BagRecording whole() const {
    BagRecording files(paths);
    files.on_progress = on_progress;
    return files;
  }
};

// A recording opened once for several questions. Opening reads each bag's whole index (about 70
// bytes of memory and a good part of the read time per message), so a tool that lists the topics,
// counts one and streams it should do all three on one OpenBag. Not thread-safe: one thread at a
// time. The for_each_* calls stream the recording's window only, and return how many messages
// they handed over.
class OpenBag {
 public:
  // Throws InputError if a bag cannot be read, if no bag is named, or if two files' recording
  // (receive) times overlap, naming both; ConfigError for an unusable window.
  explicit OpenBag(const BagRecording& recording);
  ~OpenBag();
  OpenBag(const OpenBag&) = delete;
  OpenBag& operator=(const OpenBag&) = delete;

  // The recording's name for messages (BagRecording::name).
  const std::string& path() const { return path_; }
  // The files in the order they are read (stamp order).
  std::vector<std::string> ordered_paths() const;
  // The joins between files met by the last for_each_* call (empty for one bag).
  const std::vector<FileJoin>& joins() const { return joins_; }
  std::vector<TopicInfo> topics() const;
  // As the free choose_topic below, with the topic's type and message count.
  TopicInfo choose_topic(const std::string& requested, const std::string& datatype) const;
  // As the free for_each_* below.
  std::size_t for_each_imu(const std::string& topic, const std::function<void(const ImuRecord&)>& on_record);
  std::size_t for_each_increment(const std::string& topic,
                                 const std::function<void(const IncrementRecord&)>& on_record);
  std::size_t for_each_truth(const std::string& topic, const std::function<void(const TruthRecord&)>& on_record);
  std::size_t for_each_temperature(const std::string& topic,
                                   const std::function<void(const TemperatureRecord&)>& on_record);
  // Every message of every topic in bag (receive-time) order, as rosbag play sends them, for a
  // tool that rewrites a bag; a truncated or corrupt bag -> InputError as above.
  std::size_t for_each_message_in_order(const std::function<void(const rosbag::MessageInstance&)>& on_message);

 private:
  struct File;
  template <class Message>
  std::size_t stream(const std::string& topic, const std::string& datatype,
                     const std::function<void(const Message&)>& on_message);

  // Messages of topic (every topic when empty) over the files, whatever the window.
  std::size_t count_in_files(const std::string& topic) const;

  std::string path_;
  TimeWindow window_;
  ProgressCallback on_progress_;
  std::vector<std::unique_ptr<File>> files_;  // in stamp order
  std::vector<FileJoin> joins_;
};

// The records of one message, as the readers below give them; live nodes use the same conversion.
ImuRecord to_imu_record(const sensor_msgs::Imu& message);
IncrementRecord to_increment_record(const imu_lab::ImuIncrement& message);

// All topics of a bag with their types and counts. Throws InputError if the bag cannot be read.
std::vector<TopicInfo> list_topics(const BagRecording& recording);

// The IMU topic to read: `requested` if given (checked to exist and to be sensor_msgs/Imu),
// otherwise the only sensor_msgs/Imu topic; several candidates or none -> InputError listing them.
std::string choose_imu_topic(const BagRecording& recording, const std::string& requested);
// The same for any message type, e.g. "imu_lab/ImuIncrement".
std::string choose_topic(const BagRecording& recording, const std::string& requested, const std::string& datatype);

// Calls `on_record` for each message of `topic` in bag order. Returns the number of messages.
// A bag that ends early (truncated, unindexed) or whose chunks are corrupt -> InputError.
std::size_t for_each_imu(const BagRecording& recording, const std::string& topic,
                         const std::function<void(const ImuRecord&)>& on_record);
// The same for imu_lab/ImuIncrement and imu_lab/ImuTruth topics.
std::size_t for_each_increment(const BagRecording& recording, const std::string& topic,
                               const std::function<void(const IncrementRecord&)>& on_record);
std::size_t for_each_truth(const BagRecording& recording, const std::string& topic,
                           const std::function<void(const TruthRecord&)>& on_record);
std::size_t for_each_temperature(const BagRecording& recording, const std::string& topic,
                                 const std::function<void(const TemperatureRecord&)>& on_record);

}  // namespace ros_io
}  // namespace imu_lab
