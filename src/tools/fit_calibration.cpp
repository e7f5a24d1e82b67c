// fit_calibration: a calibration bag (IMU resting in several orientations, turned between them)
// in; the calibration YAML, the Kalibr/OpenVINS intrinsics and a text report out (all atomic).
// With --schedule (a multi_position scenario) the orientations are known (mode 1); without it
// they are estimated (mode 2, hand-turned IMU). See include/imu_lab/calib/bench_calibration.h.
#include <CLI/CLI.hpp>

#include <iostream>

#include "imu_lab/calib/bench_calibration.h"
#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/calib/calibration_report.h"
#include "imu_lab/calib/kalibr_intrinsics.h"
#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/progress.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/ros_io/bag/recording_arguments.h"
#include "imu_lab/ros_io/bag/strict_imu_reading.h"
#include "imu_lab/ros_io/node/config_paths.h"

namespace {

constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;

// "out/calibration.yaml" -> "out/calibration" + suffix.
std::string beside(const std::string& path, const std::string& suffix) {
  const auto dot = path.rfind('.');
  const auto slash = path.rfind('/');
  const bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_extension ? path.substr(0, dot) : path) + suffix;
}

imu_lab::EarthShape earth_model_named(const std::string& name) {
  if (name == "wgs84_rotating") return imu_lab::EarthShape::kWgs84Rotating;
  if (name == "sphere_non_rotating") return imu_lab::EarthShape::kSphereNonRotating;
  throw imu_lab::ConfigError("--earth-model", "earth_model", "must be wgs84_rotating or sphere_non_rotating");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Bench calibration of an IMU bag: bias and full scale/misalignment matrix of gyros and accelerometers."};
  using namespace imu_lab::option_range;
  const auto latitude_deg_range = imu_lab::option_range::latitude_deg;  // the names are taken by the options
  const auto height_m_range = imu_lab::option_range::height_m;
  imu_lab::ros_io::RecordingArguments recording;
  std::string topic, schedule_name, out_path, earth_model = "wgs84_rotating";
  double latitude_deg = 0.0, height_m = 0.0;
  std::size_t held_out_last = 0;
  imu_lab::calib::CalibrationOptions options;
  imu_lab::ros_io::add_recording_arguments(app, recording, "calibration bag", true);
  app.add_option("-o,--out", out_path, "calibration YAML to write (beside it: *_kalibr_imu_chain.yaml, *_report.txt)")
      ->required();
  app.add_option("--topic", topic, "sensor_msgs/Imu topic (default: the only one in the bag)");
  auto* schedule_option = app.add_option(
      "--schedule", schedule_name,
      "multi_position scenario (name in config/scenarios or path) giving the orientations and the site: mode 1");
  // Without a schedule the site is the reference of both triads (normal gravity, Earth rate), so
  // it is required; with one, the schedule's site is used and a second one is refused.
  auto* latitude_option = app.add_option("--latitude-deg", latitude_deg, "site latitude (required without --schedule)")
                              ->check(latitude_deg_range())
                              ->excludes(schedule_option);
  auto* height_option = app.add_option("--height-m", height_m, "site height (required without --schedule)")
                            ->check(height_m_range())
                            ->excludes(schedule_option);
  app.add_option("--earth-model", earth_model, "wgs84_rotating | sphere_non_rotating, without a schedule")
      ->capture_default_str()
      ->excludes(schedule_option);
  app.add_option("--held-out-last", held_out_last,
                 "leave the last N rests out of the fit, for the |g|/|Earth rate| check");
  app.add_flag("--g-sensitivity", options.estimate_g_sensitivity, "also fit the gyros' g-sensitivity matrix");
  app.add_option("--static-window-s", options.static_detection.window_s, "rest detection window")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--min-rest-s", options.static_detection.min_duration_s, "shortest rest")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--static-threshold-rad-s", options.static_detection.threshold_rad_s,
                 "rest threshold on the window mean rate (default: from the noise)")
      ->check(positive());
  if (const auto status = imu_lab::parse_tool_options("fit_calibration", app, argc, argv)) return *status;

  recording.on_progress = imu_lab::terminal_progress("fit_calibration", "messages");
  imu_lab::ToolInput input = recording.tool_input(topic);
  return imu_lab::run_tool_main("fit_calibration", input, [&] {
    if (!schedule_name.empty()) {
      options.schedule = imu_lab::calib::schedule_from_scenario(
          imu_lab::emulator::load_scenario(imu_lab::ros_io::resolve_config("scenarios", schedule_name)));
    } else {
      if (latitude_option->count() == 0 || height_option->count() == 0) {
        throw imu_lab::ConfigError("fit_calibration", "--latitude-deg/--height-m",
                                   "give the site's latitude and height (or --schedule): without a schedule they set "
                                   "the reference gravity and Earth rate, and a wrong site is a scale-factor error "
                                   "(latitude 0 instead of 50 degrees: about 2700 ppm)");
      }
      options.site.latitude_rad = latitude_deg * kRadPerDeg;
      options.site.height_m = height_m;
      options.site.earth_model = earth_model_named(earth_model);
    }
    const imu_lab::ros_io::BagRecording bag = recording.recording();
    input.topic = topic = imu_lab::ros_io::choose_imu_topic(bag, topic);
    std::vector<imu_lab::io::ImuRecord> samples;
    imu_lab::ros_io::for_each_imu_strictly(bag, topic,
                                           [&](const imu_lab::io::ImuRecord& record) { samples.push_back(record); });
    if (samples.size() < 2)
      throw imu_lab::InputError("bag " + bag.name() + ": topic " + topic + " has too few messages (" +
                                imu_lab::io::describe_time_window(bag.window) + ")");
    // Held out at the end, like the thesis's verification run after the calibration run.
    const std::size_t rests =
        imu_lab::calib::detect_static_intervals(samples, options.static_detection).intervals.size();
    for (std::size_t k = rests > held_out_last ? rests - held_out_last : 0; k < rests; ++k) {
      options.held_out_positions.push_back(k);
    }
    const auto result = imu_lab::calib::calibrate(samples, options);
    const double rate_hz =
        (samples.size() - 1) / imu_lab::seconds_between(samples.front().stamp_ns, samples.back().stamp_ns);
    const std::string report = imu_lab::calib::calibration_report(result);
    // The three files are one set: all new, or (on any failure) all as they were.
    imu_lab::OutputSet outputs;
    outputs.write(out_path, imu_lab::calib::calibration_yaml(result));
    outputs.write(beside(out_path, "_kalibr_imu_chain.yaml"),
                  imu_lab::calib::kalibr_imu_chain_yaml(result, topic, rate_hz));
    outputs.write(beside(out_path, "_report.txt"), report);
    outputs.commit();
    for (const std::string& warning : result.warnings) std::cerr << "fit_calibration: warning: " << warning << "\n";
    std::cout << "fit_calibration: " << bag.name() << ", " << imu_lab::io::describe_time_window(bag.window) << "\n"
              << report << "\nwrote " << out_path << ", " << beside(out_path, "_kalibr_imu_chain.yaml") << ", "
              << beside(out_path, "_report.txt") << "\n";
    return 0;
  });
}
