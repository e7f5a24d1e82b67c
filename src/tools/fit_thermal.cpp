// fit_thermal: thermal-test bag -> thermal model YAML (atomic), the per-window residual CSV and,
// on request, a PNG of bias against temperature per axis (scripts/plot_thermal.py).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/format_number.h"
#include "imu_lab/common/progress.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/emulator/earth_model.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "imu_lab/ros_io/bag/recording_arguments.h"
#include "imu_lab/ros_io/bag/thermal_bag.h"
#include "imu_lab/thermal/thermal_fit.h"
#include "imu_lab/thermal/thermal_model_yaml.h"
#include "imu_lab/thermal/thermal_residual_csv.h"

namespace {

constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;

struct Command {
  imu_lab::ros_io::RecordingArguments recording;
  std::string out_path, csv_path, plot_path;
  imu_lab::ros_io::ThermalBagTopics topics;
  imu_lab::thermal::WindowSettings windows;
  imu_lab::thermal::ThermalFitOptions fit;
  int order = 0;
  bool no_scale_factor = false;
  double latitude_deg = 0.0;
  double height_m = 0.0;
  double regime_threshold_c_s2 = 0.0;  // 0: from the data
};

std::string default_csv_path(const std::string& out_path) {
  const std::string suffix = ".yaml";
  const bool has_suffix =
      out_path.size() > suffix.size() && out_path.compare(out_path.size() - suffix.size(), suffix.size(), suffix) == 0;
  return (has_suffix ? out_path.substr(0, out_path.size() - suffix.size()) : out_path) + "_residuals.csv";
}

void print_regime(const imu_lab::ros_io::ThermalBagWindows& data) {
  const auto& regime = data.regime_switch;
  if (!regime.enabled) return;
  std::size_t dynamic = 0, static_windows = 0;
  for (const auto& window : data.windows) {
    if (!window.is_static) continue;
    ++static_windows;
    if (window.dynamic_fraction.value_or(0.0) > 0.5) ++dynamic;
  }
  std::printf(
      "fit_thermal: regime switch: |d2T/dt2| over %.4g s, %s, hold %.6g s: %zu of %zu readings over it; "
      "%zu of %zu static windows dynamic\n",
      regime.window_s,
      data.suggested_threshold
          ? ("from the data: " + data.suggested_threshold->text()).c_str()
          : ("threshold " + imu_lab::format_number(regime.threshold_c_s2, 4) + " degC/s^2").c_str(),
      regime.hold_s, data.readings_over_threshold, data.temperature_messages, dynamic, static_windows);
}

void print_summary(const imu_lab::thermal::ThermalFitResult& result) {
  std::printf("fit_thermal: %zu static windows in %zu orientations (%zu visits), valid %s\n",
              result.static_window_count, result.orientations.clusters.size(), result.visit_count,
              imu_lab::thermal::validity_range_text(result.model).c_str());
  static const char* const kAxisNames[3] = {"x", "y", "z"};
  for (const auto& axis : result.axes) {
    std::printf(
        "  %-13s %s: bias order %d, scale-factor order %d, fitted delta-bias p-p %.4g, residual rms %.4g%s "
        "(%.3g x the noise of a window mean), %zu constants\n",
        axis.triad.c_str(), kAxisNames[axis.axis], axis.bias_order, axis.scale_factor_order,
        axis.delta_bias_peak_to_peak, axis.residual_rms, axis.triad == "gyro" ? " rad/s" : " m/s^2",
        axis.residual_over_noise, axis.constant_count);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit a thermal model (bias and scale factor against temperature) to a thermal-test bag."};
  using namespace imu_lab::option_range;
  Command c;
  imu_lab::ros_io::add_recording_arguments(
      app, c.recording, "thermal-test bag: the IMU static in several orientations over a temperature profile", true);
  app.add_option("-o,--out", c.out_path, "thermal model YAML to write")->required();
  app.add_option("--csv", c.csv_path, "per-window residual CSV (default: <out>_residuals.csv)");
  app.add_option("--plot", c.plot_path, "also plot bias against temperature into this PNG (scripts/plot_thermal.py)");
  app.add_option("--topic", c.topics.imu, "sensor_msgs/Imu topic (default: the bag's only one)");
  app.add_option("--temperature-topic", c.topics.temperature, "thermosensor topic")->capture_default_str();
  app.add_option("--second-temperature-topic", c.topics.second_temperature,
                 "second, lagging thermosensor (enables the second-sensor term)");
  app.add_option("--order", c.order, "polynomial order 1..4 (default: chosen by cross-validation)")
      ->check(CLI::Range(1, 4));
  app.add_option("--max-order", c.fit.max_polynomial_order, "highest order cross-validation tries")
      ->capture_default_str()
      ->check(CLI::Range(1, 4));
  app.add_flag("--rate-term", c.fit.temperature_rate_term, "fit the dynamic-regime term in dT/dt (bias)");
  app.add_flag("--scale-factor-rate-term", c.fit.scale_factor_rate_term,
               "also a dT/dt term in the scale factor (needs opposite orientations during ramps)");
  app.add_flag("--second-sensor-scale-factor", c.fit.second_sensor_scale_factor,
               "also a scale-factor polynomial in the second thermosensor (needs --second-temperature-topic and "
               "opposite orientations while the two sensors disagree)");
  app.add_flag("--regime-switch", c.fit.regime_switch.enabled,
               "separate bias terms for the dynamic regime, where |d2T/dt2| exceeds the threshold (Golovach 2017 "
               "eqs. 3.18, 3.19)");
  app.add_option("--regime-threshold-c-s2", c.regime_threshold_c_s2,
                 "threshold on |d2T/dt2| [degC/s^2] (default: from the data, see doc/thermal.md)")
      ->check(positive());
  app.add_option("--regime-window-s", c.fit.regime_switch.window_s, "window of the d2T/dt2 estimate [s]")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--regime-hold-s", c.fit.regime_switch.hold_s,
                 "the dynamic regime lasts this long after |d2T/dt2| falls below the threshold [s]")
      ->capture_default_str()
      ->check(at_least(0.0));
  app.add_flag("--no-scale-factor", c.no_scale_factor, "fit the bias only (one orientation is enough)");
  app.add_flag("--precise-revisits", c.fit.precise_revisits,
               "orientations are repeated to arc-seconds (a rate table or fixture): one constant per orientation for "
               "every axis (default: per visit for the axes across gravity, as a hand-turned test needs)");
  app.add_flag("--gyro-scale-factor", c.fit.gyro_scale_factor,
               "fit gyro scale factor from the Earth rate (navigation-grade gyros only)");
  app.add_option("--reference-temperature-c", c.fit.reference_temperature_c, "temperature the model corrects to")
      ->capture_default_str()
      ->check(at_least(-273.15));
  app.add_option("--window-s", c.windows.window_s, "averaging window [s]")->capture_default_str()->check(positive());
  app.add_option("--rate-window-s", c.windows.rate_window_s, "window of the dT/dt estimate [s]")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--max-temperature-age-s", c.windows.max_temperature_age_s,
                 "farthest a thermosensor reading may be from an IMU stamp [s]")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--static-gyro-std-rad-s", c.windows.static_angular_rate_std_rad_s, "static-window threshold")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--static-accel-std-m-s2", c.windows.static_specific_force_std_m_s2, "static-window threshold")
      ->capture_default_str()
      ->check(positive());
  const auto* latitude_option = app.add_option("--latitude-deg", c.latitude_deg,
                                               "test site latitude (gravity and Earth rate; required with a "
                                               "scale-factor term)")
                                    ->check(latitude_deg());
  app.add_option("--height-m", c.height_m, "test site height")
      ->capture_default_str()
      ->check(imu_lab::option_range::height_m());
  if (const auto status = imu_lab::parse_tool_options("fit_thermal", app, argc, argv)) return *status;
  if (c.order > 0) c.fit.polynomial_order = c.order;
  if (c.no_scale_factor) c.fit.accelerometer_scale_factor = c.fit.gyro_scale_factor = false;
  c.fit.second_sensor_term = !c.topics.second_temperature.empty();
  c.fit.earth.latitude_rad = c.latitude_deg * kRadPerDeg;
  c.fit.earth.gravity_m_s2 =
      imu_lab::emulator::normal_gravity_m_s2(imu_lab::EarthShape::kWgs84Rotating, c.fit.earth.latitude_rad, c.height_m);
  if (c.csv_path.empty()) c.csv_path = default_csv_path(c.out_path);
  c.fit.regime_switch.threshold_c_s2 = c.regime_threshold_c_s2;

  c.recording.on_progress = imu_lab::terminal_progress("fit_thermal", "messages");
  imu_lab::ToolInput input = c.recording.tool_input(c.topics.imu);
  return imu_lab::run_tool_main("fit_thermal", input, [&] {
    // The scale-factor terms compare each orientation's output with its known input, gravity and
    // the Earth rate at the site; the bias terms do not depend on it.
    if (latitude_option->count() == 0 && (c.fit.accelerometer_scale_factor || c.fit.gyro_scale_factor)) {
      throw imu_lab::ConfigError("fit_thermal", "--latitude-deg",
                                 "give the test site's latitude (and --height-m): the scale-factor terms are "
                                 "relative to gravity and the Earth rate there; or fit the bias only "
                                 "(--no-scale-factor), which does not depend on the site");
    }
    if (c.fit.second_sensor_scale_factor && !c.fit.second_sensor_term) {
      throw imu_lab::ConfigError("fit_thermal", "--second-sensor-scale-factor",
                                 "needs the second thermosensor: give --second-temperature-topic");
    }
    if (c.fit.second_sensor_scale_factor && c.no_scale_factor) {
      throw imu_lab::ConfigError("fit_thermal", "--second-sensor-scale-factor",
                                 "is a scale-factor term; it cannot go with --no-scale-factor");
    }
    if (!c.fit.regime_switch.enabled && (app.count("--regime-threshold-c-s2") > 0 ||
                                         app.count("--regime-window-s") > 0 || app.count("--regime-hold-s") > 0)) {
      throw imu_lab::ConfigError("fit_thermal", "--regime-threshold-c-s2", "the regime options need --regime-switch");
    }
    const auto data =
        imu_lab::ros_io::read_thermal_windows(c.recording.recording(), c.topics, c.windows, c.fit.regime_switch);
    c.fit.regime_switch = data.regime_switch;
    input.topic = data.imu_topic;
    std::printf("fit_thermal: %s, %s\n", c.recording.recording().name().c_str(),
                imu_lab::io::describe_time_window(c.recording.window).c_str());
    std::printf("fit_thermal: %zu IMU samples on %s, %zu temperature readings, %zu windows of %.6g s\n",
                data.imu_messages, data.imu_topic.c_str(), data.temperature_messages, data.windows.size(),
                c.windows.window_s);
    print_regime(data);
    const auto result = imu_lab::thermal::fit_thermal_model(data.windows, c.windows.rate_window_s, c.fit);
    print_summary(result);
    for (const std::string& warning : result.warnings)
      std::fprintf(stderr, "fit_thermal: warning: %s\n", warning.c_str());
    // Model, residuals and plot are one set: all new, or (on any failure) all as they were.
    imu_lab::OutputSet outputs;
    imu_lab::thermal::save_thermal_model(outputs.stage(c.out_path), result.model, &result);
    const std::string staged_csv = outputs.stage(c.csv_path);
    imu_lab::thermal::write_thermal_residual_csv(staged_csv, result);
    if (!c.plot_path.empty()) {
      const std::string problem =
          imu_lab::ros_io::run_plot_script("plot_thermal.py", {staged_csv, outputs.stage(c.plot_path)});
      if (!problem.empty())
        throw imu_lab::OutputError("cannot plot " + c.plot_path + ": " + problem + "; nothing written");
    }
    outputs.commit();
    std::printf("fit_thermal: wrote %s and %s%s\n", c.out_path.c_str(), c.csv_path.c_str(),
                c.plot_path.empty() ? "" : (" and " + c.plot_path).c_str());
    return 0;
  });
}
