#include "imu_lab/ros_io/node/node_main.h"

#include <ros/ros.h>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace ros_io {

int run_node_main(int argc, char** argv, const char* node_name,
                  const std::function<void(ros::NodeHandle& node, ros::NodeHandle& private_node)>& body) {
  ros::init(argc, argv, node_name);
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    body(node, private_node);
  } catch (const ConfigError& error) {
    ROS_FATAL("%s: bad configuration: %s", node_name, error.what());
    return 2;
  } catch (const std::exception& error) {
    ROS_FATAL("%s: %s", node_name, error.what());
    return 1;
  }
  return 0;
}

}  // namespace ros_io
}  // namespace imu_lab
