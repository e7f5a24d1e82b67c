// The calibration_corrector node (also the nodelet imu_lab/CalibrationCorrectorNodelet): applies a
// bench calibration (fit_calibration's YAML) to an IMU stream, sample by sample:
//   specific force = K_a^-1 (a - b_a), angular rate = K_g^-1 (w - b_g - G * specific force).
// In the chain it follows thermal compensation (calibration is fitted on compensated data).
// Subscribes: imu/thermal (sensor_msgs/Imu; remap to any Imu topic). Publishes: imu/corrected
// (same header and orientation; covariances carried through K^-1 C K^-T), /diagnostics.
// Parameters: calibration_file (required), queue_size (1000), expected_rate_hz, gap_factor (3.0):
// input_health.h.
// Samples with NaN/Inf are dropped, logged (throttled) and counted; stamps are checked for rate,
// gaps and order (reported, the samples still corrected); the node keeps running.
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

#include "imu_lab/calib/imu_calibration.h"
#include "imu_lab/ros_io/node/input_health.h"

namespace imu_lab {
namespace ros_io {

// The corrected message (header, orientation and its covariance copied).
sensor_msgs::Imu corrected_message(const sensor_msgs::Imu& input, const calib::ImuCalibration& calibration);

class CalibrationCorrectorNode {
 public:
  // Throws ConfigError naming the parameter or the calibration file's key that is wrong.
  CalibrationCorrectorNode(ros::NodeHandle& node, ros::NodeHandle& private_node);

 private:
  void on_imu(const sensor_msgs::Imu::ConstPtr& message);
  void report(diagnostic_updater::DiagnosticStatusWrapper& status);

  std::mutex mutex_;  // a nodelet may run the callback and the diagnostics timer on several threads
  calib::ImuCalibration calibration_;
  std::string calibration_file_;
  ros::Subscriber subscriber_;
  ros::Publisher publisher_;
  diagnostic_updater::Updater diagnostics_;
  ros::WallTimer diagnostics_timer_;
  std::optional<InputHealth> health_;
  std::uint64_t corrected_ = 0;
};

}  // namespace ros_io
}  // namespace imu_lab
