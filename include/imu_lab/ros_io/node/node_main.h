// Every node's main(): ros::init, then `body` builds the node class and runs it; a refusal
// becomes one ROS_FATAL line naming the node and an exit status (2 for a bad configuration,
// 1 for anything else), so all nodes fail the same readable way.
#pragma once

#include <ros/node_handle.h>

#include <functional>

namespace imu_lab {
namespace ros_io {

int run_node_main(int argc, char** argv, const char* node_name,
                  const std::function<void(ros::NodeHandle& node, ros::NodeHandle& private_node)>& body);

}  // namespace ros_io
}  // namespace imu_lab
