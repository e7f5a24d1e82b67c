#include "imu_lab/ros_io/bag/atomic_bag.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace ros_io {

AtomicBag::AtomicBag(const std::string& path)
    : path_(path), temporary_path_(path + ".tmp." + std::to_string(::getpid())), bag_(std::make_unique<rosbag::Bag>()) {
  try {
    bag_->open(temporary_path_, rosbag::bagmode::Write);
  } catch (const rosbag::BagException& error) {
    throw OutputError("cannot write bag " + path + ": " + error.what());
  }
}

AtomicBag::~AtomicBag() {
  if (!committed_) abandon();
}

void AtomicBag::commit() {
  try {
    bag_->close();
  } catch (const rosbag::BagException& error) {
    fail(error.what());
  }
  // Flushed before the rename like every other kept file, so a power cut cannot leave the new
  // name on an empty bag.
  move_into_place(temporary_path_, path_, "cannot write bag " + path_);
  committed_ = true;
}

void AtomicBag::fail(const std::string& what_rosbag_said) {
  // rosbag's messages ("Error seeking", "Error writing to file") leave out the system's reason
  // (no space left, file too large), which errno still holds.
  const int cause = errno;
  abandon();
  throw OutputError("cannot write bag " + path_ + ": " + what_rosbag_said +
                    (cause != 0 ? std::string(": ") + std::strerror(cause) : std::string()) +
                    "; the previous file, if any, is kept");
}

void AtomicBag::abandon() noexcept {
  if (bag_) {
    try {
      bag_->close();
    } catch (...) {
      // A rosbag::Bag whose close failed stays open and its destructor closes again, which throws
      // and, while an exception unwinds, aborts the process. So it is never destroyed: released
      // (a few kB and a descriptor on the removed temporary, until the tool exits).
      static_cast<void>(bag_.release());
    }
    bag_.reset();
  }
  std::remove(temporary_path_.c_str());
}

}  // namespace ros_io
}  // namespace imu_lab
