#include "imu_lab/ros_io/node/launch_parent.h"

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>

namespace imu_lab {
namespace ros_io {

std::string end_parent_roslaunch() {
  const pid_t parent = ::getppid();
  // /proc/<pid>/cmdline: the arguments separated by NULs ("/usr/bin/python3\0/usr/bin/roslaunch\0...").
  std::ifstream file("/proc/" + std::to_string(parent) + "/cmdline", std::ios::binary);
  std::string command_line((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  bool launched = false;
  for (std::size_t start = 0; start < command_line.size();) {
    const std::size_t end = std::min(command_line.find('\0', start), command_line.size());
    const std::string argument = command_line.substr(start, end - start);
    const std::size_t slash = argument.rfind('/');
    if (argument.substr(slash == std::string::npos ? 0 : slash + 1) == "roslaunch") launched = true;
    start = end + 1;
  }
  if (!launched) return "the parent process (" + std::to_string(parent) + ") is not roslaunch: nothing to end";
  // roslaunch answers with SIGINT to this node, which may end it before its buffered output is out.
  std::fflush(nullptr);
  if (::kill(parent, SIGINT) != 0) return "could not signal roslaunch (" + std::to_string(parent) + ")";
  return "asked roslaunch (" + std::to_string(parent) + ") to end the launch";
}

}  // namespace ros_io
}  // namespace imu_lab
