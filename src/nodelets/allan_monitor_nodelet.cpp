// The Allan monitor as a nodelet (imu_lab/AllanMonitorNodelet): the same node class, zero-copy
// when it shares a manager with the IMU driver. The report is written when the nodelet unloads.
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <memory>

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/node/allan_monitor_node.h"

namespace imu_lab {
namespace ros_io {

class AllanMonitorNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      monitor_ = std::make_unique<AllanMonitorNode>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const ConfigError& error) {
      NODELET_FATAL("allan_monitor: bad configuration: %s", error.what());
      throw;
    }
  }

  std::unique_ptr<AllanMonitorNode> monitor_;
};

}  // namespace ros_io
}  // namespace imu_lab

PLUGINLIB_EXPORT_CLASS(imu_lab::ros_io::AllanMonitorNodelet, nodelet::Nodelet)
