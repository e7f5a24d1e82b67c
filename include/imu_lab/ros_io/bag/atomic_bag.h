// A bag that appears at its path only when complete: written under a temporary name beside
// the target and renamed on commit(). A tool that dies mid-write leaves no partial bag, and one
// whose write fails (disk full) gets an OutputError naming the bag and the cause, keeps the old
// bag and leaves no temporary.
#pragma once

#include <rosbag/bag.h>

#include <memory>
#include <string>

namespace imu_lab {
namespace ros_io {

class AtomicBag {
 public:
  explicit AtomicBag(const std::string& path);
  ~AtomicBag();  // removes the temporary file unless commit() succeeded
  AtomicBag(const AtomicBag&) = delete;
  AtomicBag& operator=(const AtomicBag&) = delete;

  // rosbag::Bag::write's arguments: topic, receive time, message [, connection header].
  template <class... Arguments>
  void write(const Arguments&... arguments) {
    try {
      bag_->write(arguments...);
    } catch (const rosbag::BagException& error) {
      fail(error.what());
    }
  }
  // Closes the bag and renames it into place; throws OutputError naming the path on failure.
  void commit();

 private:
  // Abandons the bag after rosbag refused a write or the close, and throws OutputError.
  [[noreturn]] void fail(const std::string& what_rosbag_said);
  void abandon() noexcept;

  std::string path_;
  std::string temporary_path_;
  std::unique_ptr<rosbag::Bag> bag_;
  bool committed_ = false;
};

}  // namespace ros_io
}  // namespace imu_lab
