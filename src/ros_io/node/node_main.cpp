#include "imu_lab/ros_io/node/node_main.h"

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <atomic>
#include <csignal>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace ros_io {
namespace {

// Set from a signal handler: lock-free atomics are async-signal-safe.
std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

extern "C" void on_sigint(int) { stop_requested = true; }

}  // namespace

int run_node_main(int argc, char** argv, const char* node_name,
                  const std::function<void(ros::NodeHandle& node, ros::NodeHandle& private_node)>& body,
                  NodeStop stop) {
  if (stop == NodeStop::kFinishConnected) {
    ros::init(argc, argv, node_name, ros::init_options::NoSigintHandler);
    std::signal(SIGINT, on_sigint);
  } else {
    ros::init(argc, argv, node_name);
  }
  int status = 0;
  {
    ros::NodeHandle node;
    ros::NodeHandle private_node("~");
    try {
      body(node, private_node);
    } catch (const ConfigError& error) {
      ROS_FATAL("%s: bad configuration: %s", node_name, error.what());
      status = 2;
    } catch (const std::exception& error) {
      ROS_FATAL("%s: %s", node_name, error.what());
      status = 1;
    }
  }
  ros::shutdown();
  return status;
}

void spin_until_stopped() {
  // The wait is short so that a signal between two waits is seen promptly.
  while (ros::ok() && !stop_requested) ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.05));
}

void request_stop() { stop_requested = true; }

}  // namespace ros_io
}  // namespace imu_lab
