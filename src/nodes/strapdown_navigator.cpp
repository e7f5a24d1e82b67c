// strapdown_navigator: alignment, then strapdown navigation of a live IMU topic
// (see include/imu_lab/ros_io/node/strapdown_navigator_node.h).
#include <ros/ros.h>

#include "imu_lab/ros_io/node/node_main.h"
#include "imu_lab/ros_io/node/strapdown_navigator_node.h"

int main(int argc, char** argv) {
  return imu_lab::ros_io::run_node_main(argc, argv, "strapdown_navigator",
                                        [](ros::NodeHandle& node, ros::NodeHandle& private_node) {
                                          imu_lab::ros_io::StrapdownNavigatorNode navigator(node, private_node);
                                          ros::spin();
                                        });
}
