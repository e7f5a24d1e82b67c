#include "imu_lab/ros/atomic_bag.h"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>

#include "imu_lab/common/atomic_file.h"

namespace imu_lab {
namespace ros_io {

AtomicBag::AtomicBag(const std::string& path)
    : path_(path), temporary_path_(path + ".tmp." + std::to_string(::getpid())) {
  try {
    bag_.open(temporary_path_, rosbag::bagmode::Write);
  } catch (const rosbag::BagException& error) {
    throw std::runtime_error("cannot write bag " + path + ": " + error.what());
  }
}

AtomicBag::~AtomicBag() {
  if (committed_) return;
  try {
    bag_.close();
  } catch (...) {
  }
  std::remove(temporary_path_.c_str());
}

void AtomicBag::commit() {
  bag_.close();
  // Flushed before the rename like every other kept file, so a power cut cannot leave the new
  // name on an empty bag.
  move_into_place(temporary_path_, path_, "cannot write bag " + path_);
  committed_ = true;
}

}  // namespace ros_io
}  // namespace imu_lab
