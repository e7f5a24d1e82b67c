// thermal_compensator: a live IMU topic corrected to the thermal model's reference temperature
// (see include/imu_lab/ros/thermal_compensator_node.h).
#include <ros/ros.h>

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros/thermal_compensator_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "thermal_compensator");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    imu_lab::ros_io::ThermalCompensatorNode compensator(node, private_node);
    ros::spin();
  } catch (const imu_lab::ConfigError& error) {
    ROS_FATAL("thermal_compensator: bad configuration: %s", error.what());
    return 2;
  } catch (const std::exception& error) {
    ROS_FATAL("thermal_compensator: %s", error.what());
    return 1;
  }
  return 0;
}
