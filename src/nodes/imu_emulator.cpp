// imu_emulator: publishes an emulated IMU live (see include/imu_lab/ros/imu_emulator_node.h).
#include <ros/ros.h>

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros/imu_emulator_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "imu_emulator");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    imu_lab::ros_io::ImuEmulatorNode emulator(node, private_node);
    emulator.run();
  } catch (const imu_lab::ConfigError& error) {
    ROS_FATAL("imu_emulator: bad configuration: %s", error.what());
    return 2;
  } catch (const std::exception& error) {
    ROS_FATAL("imu_emulator: %s", error.what());
    return 1;
  }
  return 0;
}
