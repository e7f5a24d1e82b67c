// The allan_monitor node's ROS parameters (private namespace) -> AllanMonitorSettings.
//   input_type (imu | increment; imu), statistics ([oadev]: any of oadev adev mdev ohdev hdev tdev
//   totdev akdev hkdev), publish_period_s (1.0), report_dir ($ROS_HOME/allan_report, ROS_HOME
//   defaulting to ~/.ros), plot (true), checkpoint_path ("" = no checkpoints),
//   checkpoint_period_s (60), resume (false), queue_size (20000); identify (true: fit the noise
//   model with every report), identify_period_s (0: with reports only; > 0: also this often, on
//   its own thread), bootstrap_replicas (0 = off; >= 2: bootstrap sigmas, slow);
//   on_input_end (keep_running | exit | end_launch; keep_running): what the node does once its
//   input topic, having had a publisher, has none left (a replayed bag ended): nothing; write the
//   report and exit, as on shutdown; or that, and end the roslaunch that started it as Ctrl-C
//   would (only when its parent process is roslaunch);
//   the engine's (streaming_options.h): points_per_decade (10), max_tau_s (1e4),
//   exact_max_averaging_factor (1000), confidence (0.683), warm_up_sample_count (1000),
//   gap_factor (1.5). Gaps always split and pool: a live node never stops on bad stamps.
//   impulse_screen (true: knocks and spikes are reported and their samples kept from the engine,
//   impulse_screen.h), impulse_threshold_sigma (12); level_shift_screen (true: steps in the level
//   are reported and the run split there, level_shift_screen.h), level_shift_threshold_sigma (10),
//   level_shift_window_s (10).
#pragma once

#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/impulse_screen.h"
#include "imu_lab/allan/level_shift_screen.h"
#include "imu_lab/allan/streaming_options.h"
#include "imu_lab/pipeline/allan_noise_report.h"
#include "imu_lab/pipeline/allan_samples.h"

namespace imu_lab {
namespace ros_io {

struct AllanMonitorSettings {
  pipeline::AllanInput input = pipeline::AllanInput::kRate;
  std::vector<allan::Statistic> statistics = {allan::Statistic::kOverlappingAllan};
  double publish_period_s = 1.0;
  std::string report_dir;
  bool plot = true;
  std::string checkpoint_path;
  double checkpoint_period_s = 60.0;
  bool resume = false;
  int queue_size = 20000;
  pipeline::AllanIdentifyOptions identify;
  double identify_period_s = 0.0;
  enum class InputEnd { kKeepRunning, kExit, kEndLaunch };
  InputEnd on_input_end = InputEnd::kKeepRunning;
  allan::StreamingOptions engine;
  allan::ImpulseScreenOptions screen;           // channel_count and gap_factor follow the engine's
  allan::LevelShiftScreenOptions level_shifts;  // likewise
};

// Throws ConfigError naming the parameter that is wrong.
AllanMonitorSettings load_allan_monitor_settings(const ros::NodeHandle& private_node);

// "oadev" -> Statistic::kOverlappingAllan, ...; throws ConfigError naming `key` for an unknown name.
allan::Statistic parse_statistic(const std::string& key, const std::string& name);

}  // namespace ros_io
}  // namespace imu_lab
