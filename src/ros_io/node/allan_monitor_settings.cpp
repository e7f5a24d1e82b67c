#include "imu_lab/ros_io/node/allan_monitor_settings.h"

#include <cmath>
#include <cstdlib>

#include "imu_lab/allan/streaming_snapshot.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/node/node_parameters.h"

namespace imu_lab {
namespace ros_io {
namespace {

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
  settings.input = pipeline::parse_allan_input(private_node.resolveName("input_type"),
                                               parameter<std::string>(private_node, "input_type", "imu"));
  if (has_parameter(private_node, "statistics")) {
    const auto statistic_names = parameter(private_node, "statistics", std::vector<std::string>());
    if (statistic_names.empty()) throw parameter_error(private_node, "statistics", "lists no statistic");
    settings.statistics.clear();
    for (const auto& name : statistic_names) {
      settings.statistics.push_back(parse_statistic(private_node.resolveName("statistics"), name));
    }
  }
  settings.publish_period_s = positive_parameter(private_node, "publish_period_s", settings.publish_period_s);
  settings.report_dir = parameter<std::string>(private_node, "report_dir", "");
  if (settings.report_dir.empty()) settings.report_dir = default_report_dir();
  settings.plot = parameter(private_node, "plot", settings.plot);
  settings.checkpoint_path = parameter<std::string>(private_node, "checkpoint_path", "");
  settings.checkpoint_period_s = positive_parameter(private_node, "checkpoint_period_s", settings.checkpoint_period_s);
  settings.resume = parameter(private_node, "resume", settings.resume);
  if (settings.resume && settings.checkpoint_path.empty()) {
    throw parameter_error(private_node, "resume", "is true but checkpoint_path is not set");
  }
  settings.queue_size = positive_parameter(private_node, "queue_size", settings.queue_size);
  settings.identify.enabled = parameter(private_node, "identify", settings.identify.enabled);
  settings.identify_period_s = non_negative_parameter(private_node, "identify_period_s", settings.identify_period_s);
  const std::string on_input_end = parameter<std::string>(private_node, "on_input_end", "keep_running");
  if (on_input_end == "keep_running") {
    settings.on_input_end = AllanMonitorSettings::InputEnd::kKeepRunning;
  } else if (on_input_end == "exit") {
    settings.on_input_end = AllanMonitorSettings::InputEnd::kExit;
  } else if (on_input_end == "end_launch") {
    settings.on_input_end = AllanMonitorSettings::InputEnd::kEndLaunch;
  } else {
    throw parameter_error(private_node, "on_input_end",
                          "is '" + on_input_end + "': it must be keep_running, exit or end_launch");
  }
  settings.identify.bootstrap_replicas =
      parameter(private_node, "bootstrap_replicas", settings.identify.bootstrap_replicas);
  const std::string replicas_problem = pipeline::bootstrap_replicas_problem(settings.identify.bootstrap_replicas);
  if (!replicas_problem.empty()) {
    throw parameter_error(private_node, "bootstrap_replicas", replicas_problem);
  }

  allan::StreamingOptions& engine = settings.engine;
  engine.channel_count = pipeline::kAllanChannelCount;
  engine.input_kind = pipeline::engine_input_kind(settings.input);
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

  allan::ImpulseScreenOptions& screen = settings.screen;
  screen.enabled = parameter(private_node, "impulse_screen", screen.enabled);
  screen.threshold_sigma = parameter(private_node, "impulse_threshold_sigma", screen.threshold_sigma);
  if (!(screen.threshold_sigma > allan::kScaleClipSigma) || !std::isfinite(screen.threshold_sigma)) {
    throw parameter_error(private_node, "impulse_threshold_sigma",
                          "must be a number above 3 (robust scales of the deviation; 12 is the default)");
  }
  screen.channel_count = engine.channel_count;
  screen.gap_factor = engine.gap_factor;
  screen.validate();

  allan::LevelShiftScreenOptions& shifts = settings.level_shifts;
  shifts.enabled = parameter(private_node, "level_shift_screen", shifts.enabled);
  shifts.threshold_sigma = parameter(private_node, "level_shift_threshold_sigma", shifts.threshold_sigma);
  if (!(shifts.threshold_sigma > allan::kLevelShiftClipSigma) || !std::isfinite(shifts.threshold_sigma)) {
    throw parameter_error(private_node, "level_shift_threshold_sigma",
                          "must be a number above 3 (robust scales of the difference; 10 is the default)");
  }
  shifts.window_s = parameter(private_node, "level_shift_window_s", shifts.window_s);
  if (!(shifts.window_s > 0.0 && shifts.window_s <= 300.0)) {
    throw parameter_error(private_node, "level_shift_window_s", "must lie above 0 and at most 300 s (default 10)");
  }
  shifts.channel_count = engine.channel_count;
  shifts.gap_factor = engine.gap_factor;
  shifts.validate();
  return settings;
}

}  // namespace ros_io
}  // namespace imu_lab
