#include "imu_lab/ros_io/node/imu_emulator_node.h"

#include <algorithm>
#include <boost/make_shared.hpp>
#include <cmath>

#include "imu_lab/ros_io/msg/emulator_messages.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "imu_lab/ros_io/node/node_parameters.h"

namespace imu_lab {
namespace ros_io {

ImuEmulatorNode::ImuEmulatorNode(ros::NodeHandle& node, ros::NodeHandle& private_node) {
  const std::string profile_name = parameter<std::string>(private_node, "profile", "tactical_mems");
  const std::string scenario_name = parameter<std::string>(private_node, "scenario", "static");
  const auto profile = emulator::load_sensor_profile(resolve_config("sensors", profile_name));
  const auto scenario = emulator::load_scenario(resolve_config("scenarios", scenario_name));

  emulator::EmulatorSettings settings;
  settings.rate_hz = positive_parameter(private_node, "rate_hz", 200.0);
  settings.seed = static_cast<std::uint64_t>(parameter(private_node, "seed", 1));
  const double start_time_s = non_negative_parameter(private_node, "start_time_s", 0.0);
  settings.start_time_s = start_time_s > 0.0 ? start_time_s : ros::WallTime::now().toSec();
  realtime_factor_ = positive_parameter(private_node, "realtime_factor", 1.0);
  duration_s_ = non_negative_parameter(private_node, "duration_s", 0.0);
  frame_id_ = parameter<std::string>(private_node, "frame_id", "imu_link");
  publish_truth_ = parameter(private_node, "publish_truth", true);
  publish_increments_ = parameter(private_node, "publish_increments", true);
  emulator_ = std::make_unique<emulator::ImuEmulator>(profile, scenario, settings);

  // Large queues: a burst after a stall must not drop samples.
  const int queue = 4 * static_cast<int>(std::ceil(settings.rate_hz)) + 100;
  raw_publisher_ = node.advertise<sensor_msgs::Imu>("imu/raw", queue);
  temperature_publisher_ = node.advertise<sensor_msgs::Temperature>("imu/temperature", queue);
  if (scenario.thermal && scenario.thermal->second_sensor_time_constant_s) {
    second_temperature_publisher_ = node.advertise<sensor_msgs::Temperature>("imu/temperature2", queue);
  }
  if (publish_truth_) truth_publisher_ = node.advertise<imu_lab::ImuTruth>("imu/truth", queue);
  if (publish_increments_) increment_publisher_ = node.advertise<imu_lab::ImuIncrement>("imu/increment", queue);

  diagnostics_.setHardwareID("imu_lab emulator: " + profile.name);
  diagnostics_.add("emulator", this, &ImuEmulatorNode::report);
  ROS_INFO("imu_emulator: %s in %s at %.6g Hz (seed %llu), first stamp %.9f", profile.name.c_str(),
           scenario.type.c_str(), settings.rate_hz, static_cast<unsigned long long>(settings.seed),
           settings.start_time_s + emulator_->sample_interval_s());
}

void ImuEmulatorNode::publish_next() {
  const emulator::EmulatedSample sample = emulator_->next();
  const double interval_s = emulator_->sample_interval_s();
  EmulatorMessages messages = to_messages(sample, interval_s, frame_id_);
  // Shared pointers: a nodelet in the same manager gets this very message (no serialisation, no copy).
  raw_publisher_.publish(boost::make_shared<sensor_msgs::Imu>(std::move(messages.raw)));
  temperature_publisher_.publish(boost::make_shared<sensor_msgs::Temperature>(std::move(messages.temperature)));
  if (messages.second_temperature) {
    second_temperature_publisher_.publish(
        boost::make_shared<sensor_msgs::Temperature>(std::move(*messages.second_temperature)));
  }
  if (publish_truth_) truth_publisher_.publish(boost::make_shared<imu_lab::ImuTruth>(std::move(messages.truth)));
  if (publish_increments_) {
    increment_publisher_.publish(boost::make_shared<imu_lab::ImuIncrement>(std::move(messages.increment)));
  }
}

void ImuEmulatorNode::run(const std::function<bool()>& keep_running) {
  const double interval_s = emulator_->sample_interval_s();
  const std::uint64_t last_sample =
      duration_s_ > 0.0 ? static_cast<std::uint64_t>(std::llround(duration_s_ / interval_s)) : UINT64_MAX;
  const ros::WallTime wall_start = ros::WallTime::now();
  while (ros::ok() && emulator_->samples_emitted() < last_sample) {
    const double emulated_elapsed_s = (ros::WallTime::now() - wall_start).toSec() * realtime_factor_;
    const auto due = std::min<std::uint64_t>(last_sample, static_cast<std::uint64_t>(emulated_elapsed_s / interval_s));
    if (due > emulator_->samples_emitted() + 1) ++bursts_;
    while (emulator_->samples_emitted() < due && ros::ok()) publish_next();
    diagnostics_.update();
    if (!keep_running()) break;
    const double next_due_wall_s = (emulator_->samples_emitted() + 1) * interval_s / realtime_factor_;
    const double wait_s = next_due_wall_s - (ros::WallTime::now() - wall_start).toSec();
    if (wait_s > 0.0) ros::WallDuration(std::min(wait_s, 0.1)).sleep();
  }
  diagnostics_.force_update();
}

void ImuEmulatorNode::report(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "publishing");
  status.add("samples published", emulator_->samples_emitted());
  status.add("rate_hz", emulator_->settings().rate_hz);
  status.add("times behind the wall clock", bursts_);
}

}  // namespace ros_io
}  // namespace imu_lab
