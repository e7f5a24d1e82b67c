// The imu_emulator node: publishes an emulated IMU live, paced by the wall clock.
// Parameters (private namespace):
//   profile (tactical_mems), scenario (static): names in config/ or YAML paths
//   rate_hz (200), seed (1), frame_id (imu_link)
//   start_time_s (0 = the wall clock at start-up; >0 = that stamp, for reproducible runs)
//   realtime_factor (1.0; 2.0 publishes twice as fast as real time)
//   duration_s (0 = until shut down), publish_truth (true), publish_increments (true)
// Topics: imu/raw, imu/temperature, imu/truth, imu/increment, and imu/temperature2 when the scenario
// has a second thermosensor (relative: remap or push a namespace);
// diagnostics on /diagnostics. Messages are published as shared pointers, so subscribers in the
// same nodelet manager (the nodelet imu_lab/ImuEmulatorNodelet) receive them without a copy.
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include <functional>
#include <memory>
#include <string>

#include "imu_lab/emulator/imu_emulator.h"

namespace imu_lab {
namespace ros_io {

class ImuEmulatorNode {
 public:
  // Throws ConfigError naming the parameter or profile key that is wrong.
  ImuEmulatorNode(ros::NodeHandle& node, ros::NodeHandle& private_node);

  // Publishes until ROS shuts down, duration_s has been emulated or `keep_running` (called between
  // bursts: the node spins there, the nodelet checks for unloading) returns false. If the machine
  // falls behind, it publishes the overdue samples in a burst: every sample keeps its exact stamp.
  void run(const std::function<bool()>& keep_running);

 private:
  void publish_next();
  void report(diagnostic_updater::DiagnosticStatusWrapper& status);

  std::unique_ptr<emulator::ImuEmulator> emulator_;
  std::string frame_id_;
  double realtime_factor_ = 1.0;
  double duration_s_ = 0.0;
  bool publish_truth_ = true;
  bool publish_increments_ = true;
  ros::Publisher raw_publisher_;
  ros::Publisher temperature_publisher_;
  ros::Publisher second_temperature_publisher_;  // valid only with a second thermosensor
  ros::Publisher truth_publisher_;
  ros::Publisher increment_publisher_;
  diagnostic_updater::Updater diagnostics_;
  std::uint64_t bursts_ = 0;  // times the node fell behind the wall clock by more than one sample
};

}  // namespace ros_io
}  // namespace imu_lab
