// navigate: bag -> strapdown navigation (static alignment, then free inertial navigation) ->
// trajectory CSV; with the emulator's /imu/truth in the bag, also the error against it (printed,
// written as a CSV beside the trajectory and, on request, plotted). The same NavigationSession as
// the strapdown_navigator node, so both give the same solution on the same bag.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/format_number.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/ros/bag_navigation.h"
#include "imu_lab/ros/config_paths.h"
#include "imu_lab/ros/navigation_csv.h"

namespace {

using imu_lab::ros_io::kDegToRad;
constexpr double kArcsecPerRad = 180.0 / M_PI * 3600.0;
constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

struct CommandLine {
  std::string bag_path, out_path, errors_path, plot_path;
  std::string input_type = "imu", heading_source = "gyrocompass", earth_model = "wgs84", vertical = "held";
  double alignment_duration_s = 300.0, initial_roll_deg = 0.0, initial_pitch_deg = 0.0, initial_yaw_deg = 0.0;
  double latitude_deg = kUnset, longitude_deg = kUnset, height_m = kUnset, reference_height_m = kUnset;
  bool no_align = false, skip_bad_samples = false;
  imu_lab::ros_io::BagNavigationOptions bag;
  imu_lab::ros_io::NavigationSettings settings;
};

void add_options(CLI::App& app, CommandLine& c) {
  app.add_option("bag", c.bag_path, "bag to navigate")->required();
  app.add_option("-o,--out", c.out_path, "trajectory CSV to write")->required();
  app.add_option("--errors-out", c.errors_path, "error CSV (default: <out>_errors.csv, only with truth)");
  app.add_option("--plot", c.plot_path, "also plot the errors into this PNG (scripts/plot_navigation.py)");
  app.add_option("--topic", c.bag.topic, "input topic (default: the bag's only one of the input type)");
  app.add_option("--input-type", c.input_type, "imu (sensor_msgs/Imu rates) or increment (imu_lab/ImuIncrement)")
      ->capture_default_str();
  app.add_option("--truth-topic", c.bag.truth_topic, "imu_lab/ImuTruth topic to compare with")->capture_default_str();
  app.add_option("--alignment-duration-s", c.alignment_duration_s, "static alignment length [s]")->capture_default_str();
  app.add_option("--heading-source", c.heading_source, "gyrocompass or given (--initial-yaw-deg)")->capture_default_str();
  app.add_flag("--no-align", c.no_align, "start from --initial-roll/pitch/yaw-deg instead of aligning");
  app.add_option("--initial-roll-deg", c.initial_roll_deg, "given roll [deg] (with --no-align)");
  app.add_option("--initial-pitch-deg", c.initial_pitch_deg, "given pitch [deg] (with --no-align)");
  app.add_option("--initial-yaw-deg", c.initial_yaw_deg, "given yaw [deg], ENU: from east towards north");
  app.add_option("--latitude-deg", c.latitude_deg, "initial latitude (default: the truth's, if the bag has it)");
  app.add_option("--longitude-deg", c.longitude_deg, "initial longitude (default: the truth's)");
  app.add_option("--height-m", c.height_m, "initial height (default: the truth's)");
  app.add_option("--earth-model", c.earth_model, "wgs84 or sphere")->capture_default_str();
  app.add_option("--vertical", c.vertical, "vertical channel: free or held (at --reference-height-m)")
      ->capture_default_str();
  app.add_option("--reference-height-m", c.reference_height_m, "height the held channel holds (default: initial)");
  app.add_option("--gap-factor", c.settings.gap_factor, "interval over this many typical ones is a gap")
      ->capture_default_str();
  app.add_option("--every-s", c.bag.output_interval_s, "write a row at most this often [s] (0: every sample)")
      ->capture_default_str()
      ->check(imu_lab::option_range::non_negative());
  app.add_flag("--skip-bad-samples", c.skip_bad_samples, "skip NaN/unordered samples instead of refusing the bag");
}

// Command line -> settings; the initial position falls back to the bag's truth.
void fill_settings(CommandLine& c) {
  using namespace imu_lab::ros_io;
  c.bag.input_type = parse_input_type("--input-type", c.input_type);
  NavigationSettings& s = c.settings;
  s.align = !c.no_align;
  s.alignment.duration_s = c.alignment_duration_s;
  s.alignment.heading_source = parse_heading_source("--heading-source", c.heading_source);
  s.alignment.given_yaw_rad = c.initial_yaw_deg * kDegToRad;
  s.initial_roll_rad = c.initial_roll_deg * kDegToRad;
  s.initial_pitch_rad = c.initial_pitch_deg * kDegToRad;
  s.initial_yaw_rad = c.initial_yaw_deg * kDegToRad;
  if (std::isnan(c.latitude_deg) || std::isnan(c.longitude_deg) || std::isnan(c.height_m)) {
    const auto truth = first_truth(c.bag_path, c.bag.truth_topic);
    if (!truth) {
      throw imu_lab::ConfigError("navigate", "--latitude-deg/--longitude-deg/--height-m",
                                 "the bag has no " + c.bag.truth_topic + " to take the initial position from; give all three");
    }
    if (std::isnan(c.latitude_deg)) c.latitude_deg = truth->latitude_rad / kDegToRad;
    if (std::isnan(c.longitude_deg)) c.longitude_deg = truth->longitude_rad / kDegToRad;
    if (std::isnan(c.height_m)) c.height_m = truth->height_m;
  }
  s.latitude_rad = c.latitude_deg * kDegToRad;
  s.longitude_rad = c.longitude_deg * kDegToRad;
  s.height_m = c.height_m;
  s.navigator.earth = parse_earth_model("--earth-model", c.earth_model);
  s.navigator.vertical.mode = parse_vertical_channel("--vertical", c.vertical);
  s.navigator.vertical.fixed_reference_height_m = std::isnan(c.reference_height_m) ? c.height_m : c.reference_height_m;
  validate(s, "navigate");
}

void print_summary(const CommandLine& c, const imu_lab::ros_io::BagNavigationResult& result) {
  const auto& n = result.counters;
  std::printf("navigate: %s, topic %s: %zu messages, %llu used, skipped %llu invalid, %llu unordered, %llu after gaps\n",
              c.bag_path.c_str(), result.topic.c_str(), result.messages, static_cast<unsigned long long>(n.used),
              static_cast<unsigned long long>(n.invalid), static_cast<unsigned long long>(n.unordered),
              static_cast<unsigned long long>(n.gaps));
  const auto& a = *result.alignment;
  // A given attitude has no predicted error (NaN): say so rather than print "nan".
  std::string predicted = "no predicted error (heading or attitude given, not estimated)";
  if (a.predicted_error_sigma_rad.allFinite()) {
    const Eigen::Vector3d sigma_arcsec = a.predicted_error_sigma_rad * kArcsecPerRad;
    predicted = "predicted 1-sigma error E/N/U " + imu_lab::format_number(sigma_arcsec.x(), 3) + " " +
                imu_lab::format_number(sigma_arcsec.y(), 3) + " " + imu_lab::format_number(sigma_arcsec.z(), 3) + " arcsec";
  }
  std::printf("alignment (%s, %.1f s, ends %s): roll %.6f pitch %.6f yaw %.6f deg; %s\n", a.method.c_str(),
              a.duration_s, imu_lab::ros_io::format_stamp(a.stamp_ns).c_str(), a.roll_pitch_yaw_rad.x() / kDegToRad,
              a.roll_pitch_yaw_rad.y() / kDegToRad, a.roll_pitch_yaw_rad.z() / kDegToRad, predicted.c_str());
  const auto& last = result.solutions.back();
  std::printf("final (%s): lat %.9f lon %.9f deg, height %.3f m, ENU %.3f %.3f %.3f m\n",
              imu_lab::ros_io::format_stamp(last.stamp_ns).c_str(), last.latitude_rad / kDegToRad,
              last.longitude_rad / kDegToRad, last.height_m, last.position_enu_m.x(), last.position_enu_m.y(),
              last.position_enu_m.z());
  if (result.errors.empty()) return;
  double max_horizontal = 0.0, max_height = 0.0, max_attitude = 0.0;
  for (const auto& e : result.errors) {
    max_horizontal = std::max(max_horizontal, e.horizontal_position_error_m);
    max_height = std::max(max_height, std::abs(e.height_error_m));
    max_attitude = std::max(max_attitude, e.attitude_error_enu_rad.norm());
  }
  const auto& e = result.errors.back();
  std::printf("error vs truth after %.1f s: horizontal position %.4f m (max %.4f), height %.4f m (max |%.4f|), "
              "attitude E/N/U %.3f %.3f %.3f arcsec (max |%.3f|)\n",
              e.time_since_alignment_s, e.horizontal_position_error_m, max_horizontal, e.height_error_m, max_height,
              e.attitude_error_enu_rad.x() * kArcsecPerRad, e.attitude_error_enu_rad.y() * kArcsecPerRad,
              e.attitude_error_enu_rad.z() * kArcsecPerRad, max_attitude * kArcsecPerRad);
}

std::string default_errors_path(const std::string& out_path) {
  const std::string suffix = ".csv";
  const bool has_suffix = out_path.size() > suffix.size() &&
                          out_path.compare(out_path.size() - suffix.size(), suffix.size(), suffix) == 0;
  return (has_suffix ? out_path.substr(0, out_path.size() - suffix.size()) : out_path) + "_errors.csv";
}

void plot(const std::string& errors_path, const std::string& png_path, const std::string& final_png_path) {
  const std::string problem = imu_lab::ros_io::run_plot_script("plot_navigation.py", {errors_path, png_path});
  if (!problem.empty()) throw imu_lab::OutputError("cannot plot " + final_png_path + ": " + problem + "; nothing written");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Strapdown navigation of an IMU bag: trajectory CSV, and errors against the truth if the bag has it."};
  CommandLine c;
  add_options(app, c);
  if (const auto status = imu_lab::parse_tool_options("navigate", app, argc, argv)) return *status;
  imu_lab::ToolInput input{"bag", c.bag_path, c.bag.topic};
  return imu_lab::run_tool_main("navigate", input, [&] {
    fill_settings(c);
    const auto result = imu_lab::ros_io::navigate_bag(c.bag_path, c.bag, c.settings);
    const auto& n = result.counters;
    if (!c.skip_bad_samples && n.invalid + n.unordered > 0) {
      throw imu_lab::InputError("bag " + c.bag_path + ", topic " + result.topic + ": " + std::to_string(n.invalid) +
                                " samples with NaN/Inf, a value beyond +-1e100 or a bad interval and " + std::to_string(n.unordered) +
                                " unordered stamps, first " + result.first_problem +
                                "; nothing written (repair the bag, or pass --skip-bad-samples to skip them)");
    }
    print_summary(c, result);
    // Trajectory, errors and plot are one set: all new, or (on any failure) all as they were.
    imu_lab::OutputSet outputs;
    imu_lab::ros_io::write_trajectory_csv(outputs.stage(c.out_path), result.solutions);
    const std::string errors_path = c.errors_path.empty() ? default_errors_path(c.out_path) : c.errors_path;
    if (result.has_truth) {
      const std::string staged_errors = outputs.stage(errors_path);
      imu_lab::ros_io::write_error_csv(staged_errors, result.errors);
      if (!c.plot_path.empty()) plot(staged_errors, outputs.stage(c.plot_path), c.plot_path);
    } else {
      outputs.remove_at_commit(errors_path);  // an earlier run's, which would not belong to this trajectory
      if (!c.plot_path.empty()) std::cerr << "navigate: no " << c.bag.truth_topic << " in the bag, so no error to plot\n";
    }
    outputs.commit();
    std::printf("navigate: wrote %s (%zu rows)\n", c.out_path.c_str(), result.solutions.size());
    if (result.has_truth) std::printf("navigate: wrote %s (%zu rows)\n", errors_path.c_str(), result.errors.size());
    if (result.has_truth && !c.plot_path.empty()) std::printf("navigate: wrote %s\n", c.plot_path.c_str());
    return 0;
  });
}
