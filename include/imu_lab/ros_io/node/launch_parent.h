// Ending the roslaunch that started this node, as Ctrl-C in its terminal would. roslaunch ends a
// launch by itself only when a required node dies, and then prints a "REQUIRED process has died"
// banner even for a clean exit; a node whose job is done (allan_monitor after a replayed bag) asks
// its launcher to end instead. Used only where a parameter asks for it.
#pragma once

#include <string>

namespace imu_lab {
namespace ros_io {

// Sends SIGINT to the parent process if its command line names roslaunch; otherwise (rosrun, a
// shell, a nodelet manager's launcher) does nothing. Returns what it did, for the log.
std::string end_parent_roslaunch();

}  // namespace ros_io
}  // namespace imu_lab
