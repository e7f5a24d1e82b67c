#include "imu_lab/ros/atomic_bag.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

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
  if (std::rename(temporary_path_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error("cannot write bag " + path_ + ": rename failed: " + std::strerror(errno));
  }
  committed_ = true;
}

}  // namespace ros_io
}  // namespace imu_lab
