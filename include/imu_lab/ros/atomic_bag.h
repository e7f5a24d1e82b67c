// A bag that appears at its path only when complete: written under a temporary name beside
// the target and renamed on commit(). A tool that dies mid-write leaves no partial bag.
#pragma once

#include <rosbag/bag.h>

#include <string>

namespace imu_lab {
namespace ros_io {

class AtomicBag {
 public:
  explicit AtomicBag(const std::string& path);
  ~AtomicBag();  // removes the temporary file unless commit() succeeded
  AtomicBag(const AtomicBag&) = delete;
  AtomicBag& operator=(const AtomicBag&) = delete;

  rosbag::Bag& bag() { return bag_; }
  template <class Message>
  void write(const std::string& topic, const ros::Time& stamp, const Message& message) {
    bag_.write(topic, stamp, message);
  }
  // Closes the bag and renames it into place; throws std::runtime_error naming the path on failure.
  void commit();

 private:
  std::string path_;
  std::string temporary_path_;
  rosbag::Bag bag_;
  bool committed_ = false;
};

}  // namespace ros_io
}  // namespace imu_lab
