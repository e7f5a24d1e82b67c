// allan: bag -> the nine Allan-family stability curves (CSV per statistic), a YAML summary of the
// stamps and channels, the identified noise model (noise.yaml; kalibr_imu.yaml for Kalibr,
// kalibr_imu_chain.yaml for OpenVINS; partial curves) and a plot, in one streaming pass (see
// include/imu_lab/ros_io/bag/allan_bag_pass.h, allan_report.h and allan_noise_report.h). Nothing
// is written unless the whole pass succeeds.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/progress.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/identify/fit_options.h"
#include "imu_lab/ros_io/bag/allan_bag_pass.h"
#include "imu_lab/ros_io/bag/allan_report.h"
#include "imu_lab/pipeline/noise_table.h"
#include "imu_lab/ros_io/bag/recording_arguments.h"

namespace {

// What a user came for first: the Kalibr numbers, the IEEE terms per axis and the warnings in
// plain words (pipeline/noise_table.h); --verbose adds the full table with every warning.
void print_noise(const imu_lab::pipeline::AllanNoiseReport& noise, bool verbose) {
  if (noise.kalibr) {
    std::printf("allan: Kalibr / OpenVINS noise model (the largest over each sensor's axes):\n%s",
                imu_lab::pipeline::format_kalibr_lines(*noise.kalibr).c_str());
  }
  if (noise.triads.empty()) return;
  std::printf("allan: noise terms per axis (IEEE Std 952; value ± 1 sigma, \"< x\": not found, at most x):\n%s",
              imu_lab::pipeline::format_ieee_table(noise.triads).c_str());
  const std::size_t warnings = imu_lab::pipeline::warning_count(noise.triads);
  if (verbose) {
    std::printf("allan: identified noise in full (noise.yaml has SI values, bounds and warnings):\n%s",
                imu_lab::pipeline::format_noise_table(noise.triads).c_str());
  } else if (warnings > 0) {
    std::printf("allan: %zu warnings, grouped (noise.yaml words each in full; --verbose prints them):\n%s", warnings,
                imu_lab::pipeline::format_grouped_findings(noise.triads).c_str());
  }
}

// "allan: wrote DIR/: a.csv b.csv ..." (every file of the report is in one directory).
void print_written(const std::vector<std::string>& paths) {
  if (paths.empty()) return;
  const std::string& first = paths.front();
  const std::size_t slash = first.rfind('/');
  const std::string directory = slash == std::string::npos ? "." : first.substr(0, slash);
  std::string names;
  for (const std::string& path : paths) names += " " + path.substr(path.rfind('/') + 1);
  std::printf("allan: wrote %s/:%s\n", directory.c_str(), names.c_str());
}

void print_summary(const imu_lab::ros_io::AllanBagPassResult& result, const imu_lab::ros_io::AllanReportFiles& files,
                   bool verbose) {
  print_noise(files.noise, verbose);
  for (const auto& problem : files.noise.problems) std::fprintf(stderr, "allan: identification: %s\n", problem.c_str());
  const auto& timing = result.snapshot.timing;
  std::printf("allan: %s, topic %s: %lld samples, tau0 %.9g s (%.6g Hz), interval jitter rms %.3g s, max %.3g s\n",
              result.bag_path.c_str(), result.topic.c_str(), static_cast<long long>(timing.input_sample_count),
              timing.tau0_s, 1.0 / timing.tau0_s, timing.interval_rms_deviation_s, timing.interval_max_deviation_s);
  if (!result.window.is_whole()) {
    std::printf("allan: time window: %s\n", imu_lab::io::describe_time_window(result.window).c_str());
  }
  if (result.files.size() > 1) {
    std::printf("allan: %zu split files read in stamp order as one recording; %s\n", result.files.size(),
                imu_lab::io::describe_joins(result.joins).c_str());
  }
  long long non_finite = 0;
  for (const auto& channel : result.snapshot.channels) non_finite += channel.non_finite_count;
  // The level-shift screen's NaNs are its own, reported with it.
  for (const std::int64_t masked : result.level_shifts.channel_masked_counts) non_finite -= masked;
  // So are the holes the impulse screen leaves: gaps to the engine, not in the input.
  const auto screen_gaps = imu_lab::pipeline::impulse_screen_gaps(timing, result.impulses, result.engine.gap_factor);
  const long long input_gaps = timing.gap_count - screen_gaps.count;
  if (input_gaps + timing.duplicate_count + timing.out_of_order_count + non_finite > 0) {
    std::printf(
        "allan: irregular input (split and pooled / dropped, see allan_summary.yaml): %lld gaps (%.6g s), "
        "%lld duplicate and %lld out-of-order stamps, %lld NaN/Inf or unusable values\n",
        input_gaps, timing.gap_time_s - screen_gaps.time_s, static_cast<long long>(timing.duplicate_count),
        static_cast<long long>(timing.out_of_order_count), non_finite);
  }
  for (const auto& [count, field, triad] :
       {std::tuple{result.messages_without_angular_rate, "angular_velocity", "gyro"},
        std::tuple{result.messages_without_specific_force, "linear_acceleration", "accelerometer"}}) {
    if (count > 0) {
      std::printf(
          "allan: %zu of %zu messages mark the %s triad as not provided (%s_covariance[0] = -1): its channels "
          "leave them out\n",
          count, result.message_count, triad, field);
    }
  }
  std::printf("%s", imu_lab::pipeline::format_impulse_events("allan: ", result.impulses).c_str());
  std::printf("%s", imu_lab::pipeline::format_level_shifts("allan: ", result.input, result.level_shifts).c_str());
  if (result.warm_up) {
    std::printf("allan: warm-up removed (warm_up.yaml):\n%s",
                imu_lab::pipeline::format_warm_up_lines("allan:   ", result.input, *result.warm_up).c_str());
  }
  std::printf("allan: output steps (LSB; none: not quantised): %s\n",
              imu_lab::pipeline::format_output_steps(result.input, result.output_steps).c_str());
  print_written(files.written);
  if (files.noise.kalibr) {
    std::printf(
        "allan: kalibr_imu.yaml and kalibr_imu_chain.yaml (OpenVINS) hold rostopic %s, the recording's: set "
        "it to the topic your IMU publishes on\n",
        files.noise.kalibr->rostopic.c_str());
  }
  if (!files.plot_problem.empty()) std::fprintf(stderr, "allan: warning: %s\n", files.plot_problem.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Allan-family stability curves of an IMU bag: CSV per statistic, YAML summary, plot."};
  imu_lab::ros_io::RecordingArguments recording;
  std::string out_directory = "allan_report";
  std::string on_gap = "split";
  std::string input = "rate";
  bool progress = false;
  bool no_plot = false;
  bool no_identify = false;
  bool verbose = false;
  imu_lab::pipeline::AllanIdentifyOptions identify;
  imu_lab::ros_io::AllanBagPassOptions options;
  auto& engine = options.engine;
  imu_lab::ros_io::add_recording_arguments(app, recording, "bag to read", true);
  app.add_option("--topic", options.topic, "topic (default: the only one of the input's message type)");
  app.add_option("-o,--out", out_directory, "report directory (created)")->capture_default_str();
  app.add_option("--input", input, "rate (sensor_msgs/Imu) or increment (imu_lab/ImuIncrement)")
      ->capture_default_str()
      ->check(CLI::IsMember({"rate", "increment"}));
  app.add_option("--points-per-decade", engine.points_per_decade, "taus per decade")->capture_default_str();
  app.add_option("--max-tau-s", engine.max_tau_s, "largest tau [s]")->capture_default_str();
  app.add_option("--exact-m", engine.exact_max_averaging_factor,
                 "largest averaging factor computed exactly (beyond: on rate averaged over 2^L samples)")
      ->capture_default_str();
  app.add_option("--confidence", engine.confidence, "two-sided confidence of the chi-squared bounds")
      ->capture_default_str();
  app.add_option("--on-gap", on_gap,
                 "split: gaps split the run and the segments are pooled, bad stamps dropped and reported; "
                 "stop: fail at the first irregular stamp")
      ->capture_default_str()
      ->check(CLI::IsMember({"split", "stop"}));
  app.add_option("--gap-factor", engine.gap_factor, "an interval above this many tau0 is a gap")->capture_default_str();
  app.add_option("--warm-up-samples", engine.warm_up_sample_count, "samples that fix tau0 and the offsets")
      ->capture_default_str();
  bool no_impulse_screen = false;
  app.add_flag("--no-impulse-screen", no_impulse_screen,
               "keep knocks and spikes in the curves (by default each is reported and its samples dropped, "
               "which splits the run there)");
  app.add_option("--impulse-threshold", options.screen.threshold_sigma,
                 "a sample deviating from its local level by more than this many robust scales is a knock or spike")
      ->capture_default_str();
  bool no_level_shift_screen = false;
  app.add_flag("--no-level-shift-screen", no_level_shift_screen,
               "keep steps in the level (a tilt, a bias jump) in the curves (by default each is reported and the "
               "samples around it dropped, which splits the run there)");
  app.add_option("--level-shift-threshold", options.level_shifts.threshold_sigma,
                 "a difference of the means of --level-shift-window-s before and after a sample above this many "
                 "robust scales is a step")
      ->capture_default_str();
  app.add_option("--level-shift-window-s", options.level_shifts.window_s,
                 "each side's window of the level-shift screen [s]")
      ->capture_default_str();
  app.add_flag("--remove-warm-up", options.warm_up.enabled,
               "fit each channel's power-on warm-up (constant + up to --warm-up-terms exponentials, on block means) "
               "and remove it before the analysis; the models, sigmas and the trend left go to warm_up.yaml");
  app.add_option("--warm-up-block-s", options.warm_up.block_s, "block length of the means the warm-up fit sees [s]")
      ->capture_default_str();
  app.add_option("--warm-up-terms", options.warm_up.fit.max_terms,
                 "most exponentials tried; each one is kept only if an F-test on the fit accepts it")
      ->capture_default_str()
      ->check(CLI::Range(1, 3));
  app.add_flag("--progress", progress, "progress bar on stderr even when it is not a terminal");
  app.add_flag("--no-plot", no_plot, "do not write allan.png");
  app.add_flag("--no-identify", no_identify,
               "do not fit the noise model (no noise.yaml, kalibr_imu.yaml, kalibr_imu_chain.yaml)");
  app.add_flag("--verbose", verbose,
               "print every identified term with its interval and shape, and every warning as noise.yaml words it "
               "(by default: the Kalibr numbers, the IEEE terms per axis and the warnings grouped)");
  app.add_option("--bootstrap-replicas", identify.bootstrap_replicas,
                 "sigmas from a parametric bootstrap with N replicas per axis (slow; 0 = the fit's moment covariance)")
      ->capture_default_str()
      ->check([](const std::string& text) {
        return imu_lab::pipeline::bootstrap_replicas_problem(std::atoi(text.c_str()));
      });
  std::vector<std::string> zero_dc_terms;
  app.add_option("--zero-dc-terms", zero_dc_terms,
                 "zero-at-DC terms the identification may also select, comma-separated (none by default): "
                 "zero_dc_family (PSD alpha f^2 exp(-beta f)), zero_dc_gaussian (alpha f^2 exp(-beta f^2)), "
                 "high_pass_white (alpha f^2 / (beta^2 + f^2))")
      ->delimiter(',')
      ->check(CLI::IsMember(imu_lab::identify::zero_dc_term_names()));
  if (const auto status = imu_lab::parse_tool_options("allan", app, argc, argv)) return *status;
  for (const std::string& name : zero_dc_terms) imu_lab::identify::allow_zero_dc_term(name, &identify.fit);
  options.input = imu_lab::pipeline::parse_allan_input("--input", input);
  identify.enabled = !no_identify;
  options.screen.enabled = !no_impulse_screen;
  options.level_shifts.enabled = !no_level_shift_screen;
  engine.stamp_policy =
      on_gap == "stop" ? imu_lab::allan::StampPolicy::kStop : imu_lab::allan::StampPolicy::kSplitAndPool;

  const imu_lab::ToolInput bag_input = recording.tool_input(options.topic);
  return imu_lab::run_tool_main("allan", bag_input, [&] {
    imu_lab::pipeline::check_warm_up_options(options.warm_up);
    if (!(options.screen.threshold_sigma > imu_lab::allan::kScaleClipSigma)) {
      throw imu_lab::ConfigError("allan", "--impulse-threshold", "must be a number of scales above 3 (default 12)");
    }
    if (!(options.level_shifts.threshold_sigma > imu_lab::allan::kLevelShiftClipSigma)) {
      throw imu_lab::ConfigError("allan", "--level-shift-threshold", "must be a number of scales above 3 (default 10)");
    }
    if (!(options.level_shifts.window_s > 0.0 && options.level_shifts.window_s <= 300.0)) {
      throw imu_lab::ConfigError("allan", "--level-shift-window-s", "must lie above 0 and at most 300 s (default 10)");
    }
    options.on_progress = imu_lab::terminal_progress("allan", "messages", progress);
    const auto result = imu_lab::ros_io::run_allan_bag_pass(recording.recording(), options);
    imu_lab::pipeline::AllanRunDescription run;
    run.bag = result.bag_path;
    run.files = result.files;
    run.window = result.window;
    run.joins = result.joins;
    run.topic = result.topic;
    run.input = result.input;
    run.engine = result.engine;
    run.impulses = result.impulses;
    run.level_shifts = result.level_shifts;
    run.output_steps = result.output_steps;
    run.warm_up = result.warm_up;
    const auto files = imu_lab::ros_io::write_allan_report(out_directory, run, result.snapshot, !no_plot, identify);
    print_summary(result, files, verbose);
    return 0;
  });
}
