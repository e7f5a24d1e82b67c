// calibration_corrector: applies a bench calibration to a live IMU topic
// (see include/imu_lab/ros/calibration_corrector_node.h).
#include <ros/ros.h>

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros/calibration_corrector_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "calibration_corrector");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    imu_lab::ros_io::CalibrationCorrectorNode corrector(node, private_node);
    ros::spin();
  } catch (const imu_lab::ConfigError& error) {
    ROS_FATAL("calibration_corrector: bad configuration: %s", error.what());
    return 2;
  } catch (const std::exception& error) {
    ROS_FATAL("calibration_corrector: %s", error.what());
    return 1;
  }
  return 0;
}
