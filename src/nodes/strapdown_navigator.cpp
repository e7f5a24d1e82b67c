// strapdown_navigator: alignment, then strapdown navigation of a live IMU topic
// (see include/imu_lab/ros/strapdown_navigator_node.h).
#include <ros/ros.h>

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros/strapdown_navigator_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "strapdown_navigator");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    imu_lab::ros_io::StrapdownNavigatorNode navigator(node, private_node);
    ros::spin();
  } catch (const imu_lab::ConfigError& error) {
    ROS_FATAL("strapdown_navigator: bad configuration: %s", error.what());
    return 2;
  } catch (const std::exception& error) {
    ROS_FATAL("strapdown_navigator: %s", error.what());
    return 1;
  }
  return 0;
}
