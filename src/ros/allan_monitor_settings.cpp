#include "imu_lab/ros/allan_monitor_settings.h"

#include <cmath>
#include <cstdlib>

#include "imu_lab/allan/streaming_snapshot.h"
#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace ros_io {
namespace {

template <class Value>
Value positive_parameter(const ros::NodeHandle& private_node, const std::string& name, Value fallback) {
  const Value value = private_node.param(name, fallback);
  if (!(value > 0) || !std::isfinite(static_cast<double>(value))) {
    throw ConfigError(private_node.resolveName(name), name, "must be a positive number");
  }
  return value;
}

std::string default_report_dir() {
  if (const char* ros_home = std::getenv("ROS_HOME")) return std::string(ros_home) + "/allan_report";
  const char* home = std::getenv("HOME");
  return std::string(home != nullptr ? home : "/tmp") + "/.ros/allan_report";
}

}  // namespace

allan::Statistic parse_statistic(const std::string& key, const std::string& name) {
  std::string known;
  for (const allan::Statistic statistic : allan::kStreamingStatistics) {
    if (allan::statistic_name(statistic) == name) return statistic;
    known += " " + allan::statistic_name(statistic);
  }
  throw ConfigError("allan statistics", key, "'" + name + "' is not one of" + known);
}

AllanMonitorSettings load_allan_monitor_settings(const ros::NodeHandle& private_node) {
  AllanMonitorSettings settings;
  settings.input = parse_allan_input(private_node.resolveName("input_type"),
                                     private_node.param<std::string>("input_type", "imu"));
  std::vector<std::string> statistic_names;
  if (private_node.getParam("statistics", statistic_names)) {
    if (statistic_names.empty()) {
      throw ConfigError(private_node.resolveName("statistics"), "statistics", "lists no statistic");
    }
    settings.statistics.clear();
    for (const auto& name : statistic_names) {
      settings.statistics.push_back(parse_statistic(private_node.resolveName("statistics"), name));
    }
  }
  settings.publish_period_s = positive_parameter(private_node, "publish_period_s", settings.publish_period_s);
  settings.report_dir = private_node.param<std::string>("report_dir", default_report_dir());
  settings.plot = private_node.param("plot", settings.plot);
  settings.checkpoint_path = private_node.param<std::string>("checkpoint_path", "");
  settings.checkpoint_period_s = positive_parameter(private_node, "checkpoint_period_s", settings.checkpoint_period_s);
  settings.resume = private_node.param("resume", settings.resume);
  if (settings.resume && settings.checkpoint_path.empty()) {
    throw ConfigError(private_node.resolveName("resume"), "resume", "is true but checkpoint_path is not set");
  }
  settings.queue_size = positive_parameter(private_node, "queue_size", settings.queue_size);
  settings.identify.enabled = private_node.param("identify", settings.identify.enabled);
  settings.identify.bootstrap_replicas = private_node.param("bootstrap_replicas", settings.identify.bootstrap_replicas);
  const std::string replicas_problem = bootstrap_replicas_problem(settings.identify.bootstrap_replicas);
  if (!replicas_problem.empty()) {
    throw ConfigError(private_node.resolveName("bootstrap_replicas"), "bootstrap_replicas", replicas_problem);
  }

  allan::StreamingOptions& engine = settings.engine;
  engine.channel_count = kAllanChannelCount;
  engine.input_kind = engine_input_kind(settings.input);
  engine.points_per_decade = positive_parameter(private_node, "points_per_decade", engine.points_per_decade);
  engine.max_tau_s = positive_parameter(private_node, "max_tau_s", engine.max_tau_s);
  engine.exact_max_averaging_factor =
      positive_parameter(private_node, "exact_max_averaging_factor", engine.exact_max_averaging_factor);
  engine.confidence = positive_parameter(private_node, "confidence", engine.confidence);
  engine.warm_up_sample_count = static_cast<std::size_t>(
      positive_parameter(private_node, "warm_up_sample_count", static_cast<int>(engine.warm_up_sample_count)));
  engine.gap_factor = positive_parameter(private_node, "gap_factor", engine.gap_factor);
  engine.stamp_policy = allan::StampPolicy::kSplitAndPool;
  engine.validate();
  return settings;
}

}  // namespace ros_io
}  // namespace imu_lab
