// The thermal compensator as a nodelet (imu_lab/ThermalCompensatorNodelet): the same node class,
// zero-copy when it shares a manager with the IMU driver and the calibration corrector.
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <memory>

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/node/thermal_compensator_node.h"

namespace imu_lab {
namespace ros_io {

class ThermalCompensatorNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      compensator_ = std::make_unique<ThermalCompensatorNode>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const ConfigError& error) {
      NODELET_FATAL("thermal_compensator: bad configuration: %s", error.what());
      throw;
    }
  }

  std::unique_ptr<ThermalCompensatorNode> compensator_;
};

}  // namespace ros_io
}  // namespace imu_lab

PLUGINLIB_EXPORT_CLASS(imu_lab::ros_io::ThermalCompensatorNodelet, nodelet::Nodelet)
