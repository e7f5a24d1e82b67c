#include "imu_lab/ros_io/node/allan_monitor_node.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "imu_lab/common/cancellation.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/common/usable_imu_values.h"
#include "imu_lab/ros_io/msg/allan_messages.h"
#include "imu_lab/ros_io/bag/allan_report.h"
#include "imu_lab/ros_io/node/launch_parent.h"
#include "imu_lab/ros_io/node/node_main.h"
#include "imu_lab/ros_io/msg/noise_messages.h"

namespace imu_lab {
namespace ros_io {
namespace {

constexpr double kLogThrottle_s = 5.0;

bool file_exists(const std::string& path) { return std::ifstream(path).good(); }

// A fresh engine, or the checkpoint's when resuming from one that exists.
std::unique_ptr<allan::StreamingAllan> make_engine(const AllanMonitorSettings& settings,
                                                   const std::string& resume_key) {
  if (!settings.resume || !file_exists(settings.checkpoint_path)) {
    if (settings.resume) {
      ROS_WARN("allan_monitor: no checkpoint at %s yet; starting from scratch", settings.checkpoint_path.c_str());
    }
    return std::make_unique<allan::StreamingAllan>(settings.engine);
  }
  try {
    auto engine =
        std::make_unique<allan::StreamingAllan>(allan::StreamingAllan::load_checkpoint(settings.checkpoint_path));
    if (engine->options().input_kind != settings.engine.input_kind ||
        engine->options().channel_count != settings.engine.channel_count) {
      throw InputError("it holds another input type than input_type says");
    }
    return engine;
  } catch (const InputError& error) {
    throw ConfigError(resume_key, "resume",
                      "cannot resume from the checkpoint " + settings.checkpoint_path + ": " + error.what() +
                          "; delete it or set resume: false");
  }
}

}  // namespace

AllanMonitorNode::AllanMonitorNode(ros::NodeHandle& node, ros::NodeHandle& private_node)
    : settings_(load_allan_monitor_settings(private_node)),
      engine_(make_engine(settings_, private_node.resolveName("resume"))),
      screen_(settings_.screen),
      shift_screen_(settings_.level_shifts),
      output_steps_(pipeline::kAllanChannelCount) {
  if (settings_.resume && engine_->input_sample_count() > 0) {
    resume_after_stamp_ns_ = engine_->last_stamp_ns();
    ROS_INFO("allan_monitor: resumed from %s: %lld samples, skipping input stamped at or before %.9f s",
             settings_.checkpoint_path.c_str(), static_cast<long long>(engine_->input_sample_count()),
             *resume_after_stamp_ns_ * 1e-9);
  }

  gyro_publisher_ = node.advertise<imu_lab::AllanDeviation>("allan/gyro", 10);
  accel_publisher_ = node.advertise<imu_lab::AllanDeviation>("allan/accel", 10);
  noise_publisher_ = node.advertise<imu_lab::NoiseParameters>("allan/noise", 1, /*latch=*/true);
  // The input health is ready before the first subscription: in a nodelet manager the callbacks
  // run on worker threads as soon as it exists (one found health_ still empty and crashed it).
  health_.emplace(node.resolveName(settings_.input == pipeline::AllanInput::kRate ? "imu/raw" : "imu/increment"),
                  load_input_health_settings(private_node, settings_.engine.gap_factor));
  snapshot_failed_condition_ = health_->define_condition("snapshots that failed (no curves published)",
                                                         diagnostic_msgs::DiagnosticStatus::ERROR);
  // Held for 30 reports (30 s): a knock marks the whole record, and a replay passes it in a blink.
  constexpr int kEventHoldReports = 30;
  impulse_condition_ = health_->define_condition(
      "knocks or spikes (impulse screen events: samples left out of the curves, the run split there)",
      diagnostic_msgs::DiagnosticStatus::WARN, kEventHoldReports);
  level_shift_condition_ =
      health_->define_condition("steps in the level (level-shift screen: the run split there)",
                                diagnostic_msgs::DiagnosticStatus::WARN, kEventHoldReports);
  if (settings_.input == pipeline::AllanInput::kRate) {
    input_subscriber_ = node.subscribe("imu/raw", settings_.queue_size, &AllanMonitorNode::on_imu, this);
  } else {
    input_subscriber_ = node.subscribe("imu/increment", settings_.queue_size, &AllanMonitorNode::on_increment, this);
  }
  write_report_service_ = private_node.advertiseService("write_report", &AllanMonitorNode::on_write_report, this);

  publish_timer_ = node.createWallTimer(ros::WallDuration(settings_.publish_period_s),
                                        [this](const ros::WallTimerEvent&) { publish_curves(); });
  if (settings_.identify.enabled && settings_.identify_period_s > 0.0) {
    identify_timer_ = node.createWallTimer(ros::WallDuration(settings_.identify_period_s),
                                           [this](const ros::WallTimerEvent&) { start_identification(); });
  }
  if (!settings_.checkpoint_path.empty()) {
    checkpoint_timer_ = node.createWallTimer(ros::WallDuration(settings_.checkpoint_period_s),
                                             [this](const ros::WallTimerEvent&) { save_checkpoint(); });
  }
  diagnostics_.setHardwareID("allan_monitor");
  diagnostics_.add("allan monitor", this, &AllanMonitorNode::report);
  diagnostics_timer_ = node.createWallTimer(ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    diagnostics_.update();
  });
  ROS_INFO("allan_monitor: %s input on %s; curves every %.3g s; report to %s%s%s",
           allan_input_datatype(settings_.input), input_subscriber_.getTopic().c_str(), settings_.publish_period_s,
           settings_.report_dir.c_str(), settings_.checkpoint_path.empty() ? "" : "; checkpoints to ",
           settings_.checkpoint_path.c_str());
}

AllanMonitorNode::~AllanMonitorNode() { finish(); }

void AllanMonitorNode::on_imu(const sensor_msgs::Imu::ConstPtr& message) {
  const ImuRecord record = to_imu_record(*message);
  // A triad not provided (covariance[0] = -1) reads as NaN, which its channels leave out.
  add(pipeline::to_allan_sample(record), message->header,
      record.has_angular_rate && record.has_specific_force ? nullptr : &record);
}

void AllanMonitorNode::on_increment(const imu_lab::ImuIncrement::ConstPtr& message) {
  add(pipeline::to_allan_sample(to_increment_record(*message)), message->header, nullptr);
}

void AllanMonitorNode::add(const pipeline::AllanSample& sample, const std_msgs::Header& header,
                           const ImuRecord* incomplete) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  if (resume_after_stamp_ns_ && sample.stamp_ns <= *resume_after_stamp_ns_) {
    ++skipped_before_checkpoint_;
    return;
  }
  const StampVerdict verdict = health_->check_stamp(sample.stamp_ns);
  if (verdict == StampVerdict::kDuplicate || verdict == StampVerdict::kOutOfOrder) {
    ROS_WARN_THROTTLE(kLogThrottle_s,
                      "allan_monitor: stamp %.9f s not after the previous one: sample dropped "
                      "(counted in diagnostics)",
                      sample.stamp_ns * 1e-9);
  }
  if (incomplete != nullptr) {
    health_->check_values(*incomplete);
    ROS_WARN_THROTTLE(kLogThrottle_s,
                      "allan_monitor: a sample at %.9f s without angular rate or specific force "
                      "(covariance[0] = -1): that triad's channels leave it out (counted in diagnostics)",
                      sample.stamp_ns * 1e-9);
  } else if (std::any_of(sample.values.begin(), sample.values.end(), [](double v) { return !std::isfinite(v); })) {
    health_->count_non_finite();
    ROS_WARN_THROTTLE(kLogThrottle_s, "allan_monitor: NaN/Inf value at %.9f s excluded (counted in diagnostics)",
                      sample.stamp_ns * 1e-9);
  } else if (!std::all_of(sample.values.begin(), sample.values.end(), is_usable_imu_value)) {
    health_->count_too_large();
    ROS_WARN_THROTTLE(kLogThrottle_s,
                      "allan_monitor: a value beyond +-%.0e at %.9f s excluded from its channel "
                      "(counted in diagnostics)",
                      kLargestUsableImuValue, sample.stamp_ns * 1e-9);
  }
  output_steps_.push(sample.values.data());
  // The engine splits at gaps and drops unordered stamps itself (streaming_options.h), also at the
  // holes the screen leaves.
  screen_.push(sample.stamp_ns, sample.values.data(), screened_);
  push_screened();
  for (; counted_impulse_events_ < screen_.event_count(); ++counted_impulse_events_) {
    health_->count(impulse_condition_);
    ROS_WARN_THROTTLE(kLogThrottle_s,
                      "allan_monitor: knock or spike detected at %.9f s: its samples are left "
                      "out of the curves (listed in the report, counted in diagnostics)",
                      sample.stamp_ns * 1e-9);
  }
  for (; counted_level_shifts_ < shift_screen_.event_count(); ++counted_level_shifts_) {
    health_->count(level_shift_condition_);
    ROS_WARN_THROTTLE(kLogThrottle_s,
                      "allan_monitor: a step in the level detected before %.9f s: the run is split there "
                      "(listed in the report, counted in diagnostics)",
                      sample.stamp_ns * 1e-9);
  }
  last_header_ = header;
}

void AllanMonitorNode::push_screened() {
  shift_screen_.push(screened_, unshifted_);
  screened_.clear();
  engine_->push_block(unshifted_.stamps_ns.data(), unshifted_.values.data(), unshifted_.size());
  unshifted_.clear();
}

AllanMonitorNode::Current AllanMonitorNode::current() const {
  Current now;
  if (screen_.delayed_sample_count() == 0 && shift_screen_.delayed_sample_count() == 0) {
    now.warmed_up = engine_->warmed_up();
    now.samples = engine_->input_sample_count();
    if (now.warmed_up) now.snapshot = engine_->snapshot();
    now.impulses = screen_.report();
    now.level_shifts = shift_screen_.report();
    return now;
  }
  allan::StreamingAllan engine = *engine_;
  allan::ImpulseScreen screen = screen_;
  allan::LevelShiftScreen shift_screen = shift_screen_;
  allan::ScreenedSamples rest;
  allan::ScreenedSamples unshifted;
  screen.finish(rest);
  shift_screen.push(rest, unshifted);
  shift_screen.finish(unshifted);
  engine.push_block(unshifted.stamps_ns.data(), unshifted.values.data(), unshifted.size());
  now.warmed_up = engine.warmed_up();
  now.samples = engine.input_sample_count();
  if (now.warmed_up) now.snapshot = engine.snapshot();
  now.impulses = screen.report();
  now.level_shifts = shift_screen.report();
  return now;
}

void AllanMonitorNode::publish_curves() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  if (settings_.on_input_end != AllanMonitorSettings::InputEnd::kKeepRunning) check_input_end();
  // A node never dies on its input: whatever the curves cannot be computed from is reported.
  Current now;
  try {
    now = current();
  } catch (const std::exception& error) {
    health_->count(snapshot_failed_condition_);
    ROS_ERROR_THROTTLE(kLogThrottle_s, "allan_monitor: no curves this time: %s (counted in diagnostics)", error.what());
    return;
  }
  if (!now.warmed_up) return;
  latest_snapshot_ = std::move(now.snapshot);
  for (const allan::Statistic statistic : settings_.statistics) {
    const double confidence = engine_->options().confidence;
    gyro_publisher_.publish(
        to_allan_deviation(*latest_snapshot_, statistic, AllanTriad::kGyro, confidence, last_header_));
    accel_publisher_.publish(
        to_allan_deviation(*latest_snapshot_, statistic, AllanTriad::kAccel, confidence, last_header_));
  }
}

void AllanMonitorNode::check_input_end() {
  // This timer's callback runs on the queue the input's callbacks run on, after every message
  // read before the publisher left (rosbag play sends them all before it exits).
  if (input_subscriber_.getNumPublishers() > 0) {
    input_had_publisher_ = true;
  } else if (input_had_publisher_ && !input_end_seen_) {
    input_end_seen_ = true;
    ROS_INFO("allan_monitor: %s has no publisher left (the replay ended): writing the report and exiting%s",
             input_subscriber_.getTopic().c_str(),
             settings_.on_input_end == AllanMonitorSettings::InputEnd::kEndLaunch ? ", then ending the launch" : "");
    request_stop();  // node_main.h: main() then calls finish()
  }
}

void AllanMonitorNode::save_checkpoint() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  try {
    engine_->save_checkpoint(settings_.checkpoint_path);
  } catch (const std::exception& error) {
    ROS_ERROR_THROTTLE(kLogThrottle_s, "allan_monitor: checkpoint not saved: %s", error.what());
  }
}

pipeline::AllanRunDescription AllanMonitorNode::run_description(const Current& now) const {
  pipeline::AllanRunDescription run;
  run.topic = input_subscriber_.getTopic();
  run.input = settings_.input;
  run.engine = engine_->options();
  run.skipped_before_checkpoint = skipped_before_checkpoint_;
  run.impulses = now.impulses;
  run.level_shifts = now.level_shifts;
  run.output_steps = output_steps_.channels();
  return run;
}

void AllanMonitorNode::start_identification() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_ || identifying_) return;  // the previous fit is still running: skip this period
  Current now;
  try {
    now = current();
  } catch (const std::exception&) {
    return;  // publish_curves() reports a snapshot that cannot be made; the node goes on
  }
  if (!now.warmed_up) return;
  if (identify_thread_.joinable()) identify_thread_.join();  // finished: identifying_ is false
  identifying_ = true;
  // The fit takes seconds on a long record: off the thread that publishes the curves, on copies.
  identify_thread_ =
      std::thread([this, run = run_description(now), snapshot = std::move(now.snapshot), header = last_header_] {
        // finish() abandons it: the report it then writes identifies the whole record anyway.
        CancellationScope scope(abandon_identification_);
        try {
          noise_publisher_.publish(
              to_noise_parameters(pipeline::identify_triads(run, snapshot, settings_.identify), snapshot, header));
        } catch (const Cancelled&) {
          ROS_INFO("allan_monitor: the periodic identification in progress was abandoned for the final report");
        } catch (const std::exception& error) {
          ROS_WARN("allan_monitor: periodic identification: %s", error.what());
        }
        identifying_ = false;
      });
}

std::string AllanMonitorNode::write_report(bool publish_noise) {
  const Current now = current();
  if (!now.warmed_up) {
    throw InputError("no report yet: " + std::to_string(now.samples) + " samples on " + input_subscriber_.getTopic() +
                     ", the warm-up needs " + std::to_string(engine_->options().warm_up_sample_count));
  }
  const pipeline::AllanRunDescription run = run_description(now);
  const allan::StreamingSnapshot& snapshot = now.snapshot;
  const AllanReportFiles files =
      write_allan_report(settings_.report_dir, run, snapshot, settings_.plot, settings_.identify);
  if (settings_.identify.enabled && publish_noise) {
    noise_publisher_.publish(to_noise_parameters(files.noise, snapshot, last_header_));
  }
  std::string text = "wrote " + std::to_string(files.written.size()) + " files to " + settings_.report_dir + " (" +
                     std::to_string(now.samples) + " samples)";
  if (!files.plot_problem.empty()) text += "; no plot: " + files.plot_problem;
  for (const std::string& problem : files.noise.problems) text += "; identification: " + problem;
  return text;
}

bool AllanMonitorNode::on_write_report(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  std::lock_guard<std::mutex> lock(mutex_);
  try {
    response.message = write_report(/*publish_noise=*/true);
    response.success = true;
  } catch (const std::exception& error) {
    response.message = error.what();
    response.success = false;
  }
  ROS_INFO("allan_monitor: write_report: %s", response.message.c_str());
  return true;
}

void AllanMonitorNode::finish() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (finished_) return;
  finished_ = true;
  identify_timer_.stop();
  if (identify_thread_.joinable()) {
    abandon_identification_ = true;  // a long record's fit would hold the report past roslaunch's timeout
    lock.unlock();
    identify_thread_.join();
    lock.lock();
  }
  publish_timer_.stop();
  checkpoint_timer_.stop();
  diagnostics_timer_.stop();
  // The samples the screens still hold belong in the last checkpoint and report.
  screen_.finish(screened_);
  shift_screen_.push(screened_, unshifted_);
  screened_.clear();
  shift_screen_.finish(unshifted_);
  push_screened();
  try {
    if (!settings_.checkpoint_path.empty()) engine_->save_checkpoint(settings_.checkpoint_path);
    // No allan/noise message: nobody is left to receive it, and its record-length advice costs.
    ROS_INFO("allan_monitor: on shutdown: %s", write_report(/*publish_noise=*/false).c_str());
  } catch (const std::exception& error) {
    ROS_WARN("allan_monitor: on shutdown: %s", error.what());
  }
  if (input_end_seen_ && settings_.on_input_end == AllanMonitorSettings::InputEnd::kEndLaunch) {
    const std::string ended = end_parent_roslaunch();
    ROS_INFO("allan_monitor: %s", ended.c_str());
  }
}

void AllanMonitorNode::report(diagnostic_updater::DiagnosticStatusWrapper& status) {
  health_->fill(status, engine_->warmed_up() ? "monitoring" : "warming up");
  status.add("engine samples (with a resumed checkpoint's)", engine_->input_sample_count());
  status.add("skipped: at or before the checkpoint", skipped_before_checkpoint_);
  if (latest_snapshot_) {
    const allan::TimingReport& timing = latest_snapshot_->timing;
    status.add("engine tau0 [s]", timing.tau0_s);
    status.add("interval rms deviation [s]", timing.interval_rms_deviation_s);
    status.add("interval max deviation [s]", timing.interval_max_deviation_s);
    status.add("engine segments split at gaps", timing.gap_count);
  }
  status.add("engine state [bytes]", engine_->state_size_bytes());
  if (settings_.screen.enabled) {
    const allan::ImpulseScreenReport screen = screen_.report();
    status.add("impulse events (knocks, spikes)", screen.event_count);
    status.add("impulse samples dropped", screen.dropped_sample_count);
    if (!screen.events.empty()) {
      status.add("last impulse event onset (stamp) [s]", format_stamp_s(screen.events.back().onset_stamp_ns));
    }
  } else {
    status.add("impulse screen", "off");
  }
  if (settings_.level_shifts.enabled) {
    const allan::LevelShiftReport shifts = shift_screen_.report();
    status.add("level shifts (steps, the run split there)", shifts.event_count);
    status.add("level-shift samples masked", shifts.masked_sample_count);
    if (!shifts.events.empty()) {
      status.add("last level shift (stamp) [s]", format_stamp_s(shifts.events.back().step_stamp_ns));
    }
  } else {
    status.add("level-shift screen", "off");
  }
}

}  // namespace ros_io
}  // namespace imu_lab
