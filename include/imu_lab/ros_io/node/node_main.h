// Every node's main(): ros::init, then `body` builds the node class and runs it; a refusal
// becomes one ROS_FATAL line naming the node and an exit status (2 for a bad configuration,
// 1 for anything else), so all nodes fail the same readable way.
//
// A node with work to finish when it is stopped (allan_monitor's report) asks for
// NodeStop::kFinishConnected: SIGINT (Ctrl-C, roslaunch) then only ends spin_until_stopped(),
// and the body finishes with ROS still up, so its log lines still print and its messages still
// go out; ros::shutdown() follows the body. (ROS's own SIGINT handler shuts ROS down first, and
// rosconsole prints nothing after that.)
#pragma once

#include <ros/node_handle.h>

#include <functional>

namespace imu_lab {
namespace ros_io {

enum class NodeStop { kRosDefault, kFinishConnected };

int run_node_main(int argc, char** argv, const char* node_name,
                  const std::function<void(ros::NodeHandle& node, ros::NodeHandle& private_node)>& body,
                  NodeStop stop = NodeStop::kRosDefault);

// With kFinishConnected: runs the global callback queue until SIGINT, request_stop() or a ROS
// shutdown (rosnode kill).
void spin_until_stopped();
// Ends spin_until_stopped() as SIGINT would (a node that decides its job is done).
void request_stop();

}  // namespace ros_io
}  // namespace imu_lab
