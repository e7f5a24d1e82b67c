#include "imu_lab/ros_io/node/thermal_compensator_node.h"

#include <boost/make_shared.hpp>
#include <cmath>
#include <cstdio>

#include "imu_lab/common/stamps.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/ros_io/msg/thermal_compensated_message.h"
#include "imu_lab/ros_io/node/node_parameters.h"
#include "imu_lab/thermal/thermal_model_yaml.h"

namespace imu_lab {
namespace ros_io {
namespace {

constexpr double kLogThrottle_s = 5.0;
using Status = thermal::CompensatedSample::Status;

}  // namespace

ThermalCompensatorNode::ThermalCompensatorNode(ros::NodeHandle& node, ros::NodeHandle& private_node) {
  model_file_ = parameter<std::string>(private_node, "model_file", "");
  if (model_file_.empty())
    throw parameter_error(private_node, "model_file", "required: the YAML written by fit_thermal");
  const double max_age_s = positive_parameter(private_node, "max_temperature_age_s", 1.0);
  const int queue_size = positive_parameter(private_node, "queue_size", 1000);
  compensator_ = std::make_unique<thermal::ThermalCompensator>(thermal::load_thermal_model(model_file_), max_age_s);

  // The input health is ready before the first subscription: in a nodelet manager the callbacks
  // run on worker threads as soon as it exists (one found health_ still empty and crashed it).
  health_.emplace(node.resolveName("imu/raw"), load_input_health_settings(private_node, 3.0));
  stale_condition_ = health_->define_condition(
      "samples not published: stale temperature (no reading within max_temperature_age_s of the stamp)",
      diagnostic_msgs::DiagnosticStatus::ERROR);
  clamped_condition_ =
      health_->define_condition("samples outside the model's validity range " +
                                    thermal::validity_range_text(compensator_->model()) + " (corrected at its edge)",
                                diagnostic_msgs::DiagnosticStatus::WARN);
  temperature_dropped_condition_ = health_->define_condition(
      "temperature readings dropped (NaN or not after the previous stamp)", diagnostic_msgs::DiagnosticStatus::WARN);
  publisher_ = node.advertise<sensor_msgs::Imu>("imu/thermal", queue_size);
  imu_subscriber_ = node.subscribe("imu/raw", queue_size, &ThermalCompensatorNode::on_imu, this);
  temperature_subscriber_ =
      node.subscribe("imu/temperature", queue_size, &ThermalCompensatorNode::on_temperature, this);
  if (compensator_->model().uses_second_sensor) {
    second_temperature_subscriber_ =
        node.subscribe("imu/temperature2", queue_size, &ThermalCompensatorNode::on_second_temperature, this);
  }
  diagnostics_.setHardwareID("thermal_compensator");
  diagnostics_.add("thermal compensation", this, &ThermalCompensatorNode::report);
  diagnostics_timer_ = node.createWallTimer(ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    diagnostics_.update();
  });
  const auto& box = compensator_->model().validity;
  ROS_INFO("thermal_compensator: %s + %s -> %s with %s (valid %.2f .. %.2f degC)", imu_subscriber_.getTopic().c_str(),
           temperature_subscriber_.getTopic().c_str(), publisher_.getTopic().c_str(), model_file_.c_str(),
           box.temperature_min_c, box.temperature_max_c);
}

void ThermalCompensatorNode::on_imu(const sensor_msgs::Imu::ConstPtr& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  const ImuRecord record = to_imu_record(*message);
  health_->check_stamp(record.stamp_ns);
  health_->check_values(record);  // an unusable sample is then refused by the compensator too
  std::vector<thermal::CompensatedSample> ready;
  if (!compensator_->add_imu(record, &ready)) {
    ROS_WARN_THROTTLE(kLogThrottle_s,
                      "thermal_compensator: dropped an IMU sample at %.9f (NaN/Inf, beyond +-1e100, a "
                      "triad not provided, or its stamp is not after the previous one; counted in diagnostics)",
                      seconds_from_stamp_ns(record.stamp_ns));
    return;
  }
  waiting_messages_.push_back(message);
  publish(ready);
}

void ThermalCompensatorNode::on_temperature(const sensor_msgs::Temperature::ConstPtr& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<thermal::CompensatedSample> ready;
  if (!compensator_->add_temperature(static_cast<std::int64_t>(message->header.stamp.toNSec()), message->temperature,
                                     &ready)) {
    health_->count(temperature_dropped_condition_);
    ROS_WARN_THROTTLE(kLogThrottle_s,
                      "thermal_compensator: dropped a temperature reading at %.9f (NaN or stamp "
                      "not after the previous one)",
                      message->header.stamp.toSec());
  }
  last_temperature_c_ = message->temperature;
  publish(ready);
}

void ThermalCompensatorNode::on_second_temperature(const sensor_msgs::Temperature::ConstPtr& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<thermal::CompensatedSample> ready;
  if (!compensator_->add_second_temperature(static_cast<std::int64_t>(message->header.stamp.toNSec()),
                                            message->temperature, &ready)) {
    health_->count(temperature_dropped_condition_);
  }
  publish(ready);
}

void ThermalCompensatorNode::publish(const std::vector<thermal::CompensatedSample>& ready) {
  for (const thermal::CompensatedSample& sample : ready) {
    const sensor_msgs::Imu::ConstPtr input = waiting_messages_.front();
    waiting_messages_.pop_front();
    if (sample.status == Status::kStale) {
      health_->count(stale_condition_);
      ROS_WARN_THROTTLE(kLogThrottle_s,
                        "thermal_compensator: no temperature within the maximum age of the IMU stamp "
                        "%.9f; sample not published (is %s being published?)",
                        seconds_from_stamp_ns(sample.corrected.stamp_ns), temperature_subscriber_.getTopic().c_str());
      continue;
    }
    if (sample.status == Status::kClamped) {
      health_->count(clamped_condition_);
      ROS_WARN_THROTTLE(kLogThrottle_s,
                        "thermal_compensator: %.2f degC (rate %.4f degC/s) is outside the model's "
                        "validity range; corrected at its edge",
                        sample.input.temperature_c, sample.input.rate_c_s);
    }
    // A new shared message (the input may be shared with other subscribers): nodelets downstream
    // in the same manager receive this pointer, not a copy.
    publisher_.publish(boost::make_shared<sensor_msgs::Imu>(thermal_compensated_message(*input, sample)));
    ++published_;
  }
}

void ThermalCompensatorNode::report(diagnostic_updater::DiagnosticStatusWrapper& status) {
  health_->fill(status, "compensating");
  status.add("model file", model_file_);
  status.add("validity range", thermal::validity_range_text(compensator_->model()));
  status.add("last temperature degC", last_temperature_c_);
  status.add("samples published", published_);
  status.add("samples waiting for temperature", compensator_->waiting());
}

}  // namespace ros_io
}  // namespace imu_lab
