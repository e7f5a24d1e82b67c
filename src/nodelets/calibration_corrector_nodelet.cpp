// The calibration corrector as a nodelet (imu_lab/CalibrationCorrectorNodelet): the same node
// class, zero-copy between the thermal compensator and the navigator in one manager.
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <memory>

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/node/calibration_corrector_node.h"

namespace imu_lab {
namespace ros_io {

class CalibrationCorrectorNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      corrector_ = std::make_unique<CalibrationCorrectorNode>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const ConfigError& error) {
      NODELET_FATAL("calibration_corrector: bad configuration: %s", error.what());
      throw;
    }
  }

  std::unique_ptr<CalibrationCorrectorNode> corrector_;
};

}  // namespace ros_io
}  // namespace imu_lab

PLUGINLIB_EXPORT_CLASS(imu_lab::ros_io::CalibrationCorrectorNodelet, nodelet::Nodelet)
