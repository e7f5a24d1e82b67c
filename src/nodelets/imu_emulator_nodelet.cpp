// The emulator as a nodelet (imu_lab/ImuEmulatorNodelet): the same node class, publishing from its
// own thread (the pacing loop must not block the manager's callback threads); the chain's nodelets
// in the same manager receive its messages without a copy.
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <atomic>
#include <memory>
#include <thread>

#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/node/imu_emulator_node.h"

namespace imu_lab {
namespace ros_io {

class ImuEmulatorNodelet : public nodelet::Nodelet {
 public:
  ~ImuEmulatorNodelet() override {
    unloading_ = true;
    if (publisher_thread_.joinable()) publisher_thread_.join();
  }

 private:
  void onInit() override {
    try {
      emulator_ = std::make_unique<ImuEmulatorNode>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const ConfigError& error) {
      NODELET_FATAL("imu_emulator: bad configuration: %s", error.what());
      throw;
    }
    publisher_thread_ = std::thread([this] { emulator_->run([this] { return !unloading_; }); });
  }

  std::unique_ptr<ImuEmulatorNode> emulator_;
  std::atomic<bool> unloading_{false};
  std::thread publisher_thread_;
};

}  // namespace ros_io
}  // namespace imu_lab

PLUGINLIB_EXPORT_CLASS(imu_lab::ros_io::ImuEmulatorNodelet, nodelet::Nodelet)
