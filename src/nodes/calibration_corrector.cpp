// calibration_corrector: applies a bench calibration to a live IMU topic
// (see include/imu_lab/ros_io/node/calibration_corrector_node.h).
#include <ros/ros.h>

#include "imu_lab/ros_io/node/node_main.h"
#include "imu_lab/ros_io/node/calibration_corrector_node.h"

int main(int argc, char** argv) {
  return imu_lab::ros_io::run_node_main(argc, argv, "calibration_corrector",
                                        [](ros::NodeHandle& node, ros::NodeHandle& private_node) {
                                          imu_lab::ros_io::CalibrationCorrectorNode corrector(node, private_node);
                                          ros::spin();
                                        });
}
