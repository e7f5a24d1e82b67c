// imu_emulator: publishes an emulated IMU live (see include/imu_lab/ros_io/node/imu_emulator_node.h).
#include <ros/ros.h>

#include "imu_lab/ros_io/node/node_main.h"
#include "imu_lab/ros_io/node/imu_emulator_node.h"

int main(int argc, char** argv) {
  return imu_lab::ros_io::run_node_main(
      argc, argv, "imu_emulator", [](ros::NodeHandle& node, ros::NodeHandle& private_node) {
        imu_lab::ros_io::ImuEmulatorNode emulator(node, private_node);
        emulator.run([] {
          ros::spinOnce();  // roscpp's own services (logger levels) are served from the global queue
          return true;
        });
      });
}
