// The allan_monitor node (also the nodelet imu_lab/AllanMonitorNodelet): taps an IMU topic and
// keeps the streaming Allan engine's curves up to date. Header stamps only, never arrival time.
//
// Subscribes (relative names; remap them): imu/raw (sensor_msgs/Imu) with input_type: imu, or
//   imu/increment (imu_lab/ImuIncrement) with input_type: increment.
// Publishes every publish_period_s (wall clock) once warmed up: allan/gyro and allan/accel
//   (imu_lab/AllanDeviation), one message per statistic in `statistics`; /diagnostics (input
//   rate from stamps against expected_rate_hz, gaps, NaN/Inf samples, duplicate and out-of-order
//   stamps: input_health.h; knocks and spikes the impulse screen found (a warning, counted); the
//   engine's tau0 and jitter).
// Between the input and the engine sits the impulse screen (impulse_screen.h, unless
//   impulse_screen is false): it delays the input by about guard_before_s + merge_gap_s (1.25 s),
//   and the samples of each knock or spike never reach the engine, which splits the run there.
//   The report's allan_summary.yaml lists the events and each channel's output step (LSB).
//   allan/noise (imu_lab/NoiseParameters, latched): the identified noise model, after each report
//   and every identify_period_s (0: only with reports), fitted on a thread of its own.
// Service: ~write_report (std_srvs/Trigger): the allan tool's report files (allan_report.h) in
//   report_dir, with the noise identification (allan_noise_report.h) unless identify is false;
//   written again on shutdown (SIGINT), within a few seconds: a periodic identification still
//   running is abandoned first (common/cancellation.h), since the report identifies anyway.
//   With on_input_end: exit or end_launch (a replayed bag) the node also shuts down, and writes
//   the report, once its input topic has had a publisher and has none left; end_launch then ends
//   the roslaunch that started it (characterise.launch without rviz), so the launch ends cleanly
//   with the bag instead of a required player's "has died" banner.
// Checkpoints: with checkpoint_path set, the engine's whole state is saved there (atomically)
//   every checkpoint_period_s and on shutdown; with resume: true the node starts from it and
//   skips every input stamp at or before the checkpoint's last stamp (a replay from before it).
// Parameters: allan_monitor_settings.h. Bad input is counted, logged (throttled) and reported in
// the diagnostics; the node keeps running.
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <imu_lab/ImuIncrement.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <std_srvs/Trigger.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "imu_lab/allan/impulse_screen.h"
#include "imu_lab/allan/output_step.h"
#include "imu_lab/allan/streaming_allan.h"
#include "imu_lab/ros_io/node/allan_monitor_settings.h"
#include "imu_lab/ros_io/node/input_health.h"

namespace imu_lab {
namespace ros_io {

class AllanMonitorNode {
 public:
  // Throws ConfigError naming the parameter that is wrong (or the checkpoint it cannot resume from).
  AllanMonitorNode(ros::NodeHandle& node, ros::NodeHandle& private_node);
  // Calls finish() if it has not run.
  ~AllanMonitorNode();

  // On shutdown: a last checkpoint and the report files. Runs once; later calls do nothing.
  void finish();

 private:
  void on_imu(const sensor_msgs::Imu::ConstPtr& message);
  void on_increment(const imu_lab::ImuIncrement::ConstPtr& message);
  // incomplete: the record when it lacks a triad (covariance[0] = -1), for the diagnostics.
  void add(const pipeline::AllanSample& sample, const std_msgs::Header& header, const ImuRecord* incomplete);
  void push_screened();  // what the screens passed, into the engine
  // The curves and the screen's report as they would end if the input ended now: the samples the
  // screen still holds go through a copy of it into a copy of the engine, so that what is
  // published and reported covers every sample received.
  struct Current {
    bool warmed_up = false;
    std::int64_t samples = 0;
    allan::StreamingSnapshot snapshot;
    allan::ImpulseScreenReport impulses;
    allan::LevelShiftReport level_shifts;
  };
  Current current() const;
  void publish_curves();
  // Unless on_input_end is keep_running: once the input has had a publisher and has none, shuts
  // down (finish() then writes the report), and with end_launch ends the launch too.
  void check_input_end();
  pipeline::AllanRunDescription run_description(const Current& now) const;
  // Identifies the current curves on identify_thread_ and publishes allan/noise, unless the
  // previous identification is still running.
  void start_identification();
  void save_checkpoint();
  bool on_write_report(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  // With mutex_ held; returns what was written. publish_noise: also allan/noise.
  std::string write_report(bool publish_noise);
  void report(diagnostic_updater::DiagnosticStatusWrapper& status);

  std::mutex mutex_;  // a nodelet may run the callbacks on several threads
  AllanMonitorSettings settings_;
  std::unique_ptr<allan::StreamingAllan> engine_;
  allan::ImpulseScreen screen_;
  allan::ScreenedSamples screened_;
  allan::LevelShiftScreen shift_screen_;
  allan::ScreenedSamples unshifted_;
  allan::OutputStepDetector output_steps_;
  std::int64_t counted_impulse_events_ = 0;
  std::size_t impulse_condition_ = 0;
  std::int64_t counted_level_shifts_ = 0;
  std::size_t level_shift_condition_ = 0;
  std::optional<std::int64_t> resume_after_stamp_ns_;
  std::int64_t skipped_before_checkpoint_ = 0;
  std::optional<allan::StreamingSnapshot> latest_snapshot_;
  std_msgs::Header last_header_;
  bool finished_ = false;

  ros::Subscriber input_subscriber_;
  ros::Publisher gyro_publisher_;
  ros::Publisher accel_publisher_;
  ros::Publisher noise_publisher_;
  ros::ServiceServer write_report_service_;
  ros::WallTimer publish_timer_;
  ros::WallTimer checkpoint_timer_;
  ros::WallTimer identify_timer_;
  std::thread identify_thread_;
  std::atomic<bool> identifying_{false};
  std::atomic<bool> abandon_identification_{false};  // set by finish(): the thread stops at once
  bool input_had_publisher_ = false;
  bool input_end_seen_ = false;
  diagnostic_updater::Updater diagnostics_;
  ros::WallTimer diagnostics_timer_;

  std::optional<InputHealth> health_;
  std::size_t snapshot_failed_condition_ = 0;
};

}  // namespace ros_io
}  // namespace imu_lab
