// allan_monitor: live Allan-family curves of an IMU topic, report files and checkpoints
// (see include/imu_lab/ros_io/node/allan_monitor_node.h).
#include <ros/ros.h>

#include "imu_lab/ros_io/node/node_main.h"
#include "imu_lab/ros_io/node/allan_monitor_node.h"

int main(int argc, char** argv) {
  // Stopped (Ctrl-C, roslaunch, the end of a replayed bag), it writes and logs its report while
  // still connected.
  return imu_lab::ros_io::run_node_main(
      argc, argv, "allan_monitor",
      [](ros::NodeHandle& node, ros::NodeHandle& private_node) {
        imu_lab::ros_io::AllanMonitorNode monitor(node, private_node);
        imu_lab::ros_io::spin_until_stopped();
        monitor.finish();
      },
      imu_lab::ros_io::NodeStop::kFinishConnected);
}
