// allan_monitor: live Allan-family curves of an IMU topic, report files and checkpoints
// (see include/imu_lab/ros/allan_monitor_node.h).
#include <ros/ros.h>

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros/allan_monitor_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "allan_monitor");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    imu_lab::ros_io::AllanMonitorNode monitor(node, private_node);
    ros::spin();
    monitor.finish();
  } catch (const imu_lab::ConfigError& error) {
    ROS_FATAL("allan_monitor: bad configuration: %s", error.what());
    return 2;
  } catch (const std::exception& error) {
    ROS_FATAL("allan_monitor: %s", error.what());
    return 1;
  }
  return 0;
}
