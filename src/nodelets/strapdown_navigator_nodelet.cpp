// The strapdown navigator as a nodelet (imu_lab/StrapdownNavigatorNodelet): the same node class,
// zero-copy when it shares a manager with the IMU driver or the corrector.
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <memory>

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/node/strapdown_navigator_node.h"

namespace imu_lab {
namespace ros_io {

class StrapdownNavigatorNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      navigator_ = std::make_unique<StrapdownNavigatorNode>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const ConfigError& error) {
      NODELET_FATAL("strapdown_navigator: bad configuration: %s", error.what());
      throw;
    }
  }

  std::unique_ptr<StrapdownNavigatorNode> navigator_;
};

}  // namespace ros_io
}  // namespace imu_lab

PLUGINLIB_EXPORT_CLASS(imu_lab::ros_io::StrapdownNavigatorNodelet, nodelet::Nodelet)
