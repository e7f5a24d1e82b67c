// The thermal_compensator node (also the nodelet imu_lab/ThermalCompensatorNodelet): raw IMU in,
// IMU corrected to the model's reference temperature out (thermal compensation comes before
// calibration). Each sample is corrected with the temperature at its own header stamp
// (thermal::ThermalCompensator), never the last reading to arrive.
//
// Subscribes (relative names; remap them): imu/raw (sensor_msgs/Imu), imu/temperature
//   (sensor_msgs/Temperature), imu/temperature2 (only when the model uses a second thermosensor).
// Publishes: imu/thermal (sensor_msgs/Imu; header, orientation and covariances copied), /diagnostics.
// Parameters (private): model_file (required: the YAML written by fit_thermal),
//   max_temperature_age_s (1.0): farthest a reading may be from a sample's stamp; queue_size (1000).
//   expected_rate_hz, gap_factor (3.0): input_health.h.
// Outside the model's validity range the inputs are clamped to its edge (the sample is published,
// counted, diagnostics WARN). With a stale temperature the sample is not published (an
// uncorrected sample on imu/thermal would mislead everything downstream): counted, logged
// (throttled), diagnostics ERROR. Unordered or non-finite input is dropped and counted; rate and
// gaps are reported (input_health.h).
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "imu_lab/ros_io/node/input_health.h"
#include "imu_lab/thermal/thermal_compensator.h"

namespace imu_lab {
namespace ros_io {

class ThermalCompensatorNode {
 public:
  // Throws ConfigError naming the parameter or model key that is wrong.
  ThermalCompensatorNode(ros::NodeHandle& node, ros::NodeHandle& private_node);

 private:
  void on_imu(const sensor_msgs::Imu::ConstPtr& message);
  void on_temperature(const sensor_msgs::Temperature::ConstPtr& message);
  void on_second_temperature(const sensor_msgs::Temperature::ConstPtr& message);
  void publish(const std::vector<thermal::CompensatedSample>& ready);
  void report(diagnostic_updater::DiagnosticStatusWrapper& status);

  std::mutex mutex_;  // a nodelet may run the callbacks on several threads
  std::string model_file_;
  std::unique_ptr<thermal::ThermalCompensator> compensator_;
  std::deque<sensor_msgs::Imu::ConstPtr> waiting_messages_;  // in step with the compensator's queue
  ros::Publisher publisher_;
  ros::Subscriber imu_subscriber_, temperature_subscriber_, second_temperature_subscriber_;
  diagnostic_updater::Updater diagnostics_;
  ros::WallTimer diagnostics_timer_;
  std::optional<InputHealth> health_;
  std::size_t stale_condition_ = 0, clamped_condition_ = 0, temperature_dropped_condition_ = 0;
  std::uint64_t published_ = 0;
  double last_temperature_c_ = 0.0;
};

}  // namespace ros_io
}  // namespace imu_lab
