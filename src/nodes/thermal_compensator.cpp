// thermal_compensator: a live IMU topic corrected to the thermal model's reference temperature
// (see include/imu_lab/ros_io/node/thermal_compensator_node.h).
#include <ros/ros.h>

#include "imu_lab/ros_io/node/node_main.h"
#include "imu_lab/ros_io/node/thermal_compensator_node.h"

int main(int argc, char** argv) {
  return imu_lab::ros_io::run_node_main(argc, argv, "thermal_compensator",
                                        [](ros::NodeHandle& node, ros::NodeHandle& private_node) {
                                          imu_lab::ros_io::ThermalCompensatorNode compensator(node, private_node);
                                          ros::spin();
                                        });
}
