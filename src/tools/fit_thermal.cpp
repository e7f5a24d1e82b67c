// fit_thermal: thermal-test bag -> thermal model YAML (atomic), the per-window residual CSV and,
// on request, a PNG of bias against temperature per axis (scripts/plot_thermal.py).
#include <CLI/CLI.hpp>
#include <ros/package.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/emulator/earth_model.h"
#include "imu_lab/ros/recording_arguments.h"
#include "imu_lab/ros/thermal_bag.h"
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
  double latitude_deg = 45.0;
  double height_m = 0.0;
};

std::string default_csv_path(const std::string& out_path) {
  const std::string suffix = ".yaml";
  const bool has_suffix = out_path.size() > suffix.size() &&
                          out_path.compare(out_path.size() - suffix.size(), suffix.size(), suffix) == 0;
  return (has_suffix ? out_path.substr(0, out_path.size() - suffix.size()) : out_path) + "_residuals.csv";
}

void plot(const std::string& csv_path, const std::string& png_path) {
  const std::string script = ros::package::getPath("imu_lab") + "/scripts/plot_thermal.py";
  const std::string command = "/usr/bin/python3 '" + script + "' '" + csv_path + "' '" + png_path + "'";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("plotting failed: " + command);
  std::printf("fit_thermal: wrote %s\n", png_path.c_str());
}

void print_summary(const imu_lab::thermal::ThermalFitResult& result) {
  const auto& box = result.model.validity;
  std::printf("fit_thermal: %zu static windows in %zu orientations, valid %.2f .. %.2f degC, rate %.4f .. %.4f degC/s\n",
              result.static_window_count, result.orientations.clusters.size(), box.temperature_min_c,
              box.temperature_max_c, box.rate_min_c_s, box.rate_max_c_s);
  static const char* const kAxisNames[3] = {"x", "y", "z"};
  for (const auto& axis : result.axes) {
    std::printf("  %-13s %s: bias order %d, scale-factor order %d, fitted delta-bias p-p %.4g, residual rms %.4g%s\n",
                axis.triad.c_str(), kAxisNames[axis.axis], axis.bias_order, axis.scale_factor_order,
                axis.delta_bias_peak_to_peak, axis.residual_rms, axis.triad == "gyro" ? " rad/s" : " m/s^2");
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit a thermal model (bias and scale factor against temperature) to a thermal-test bag."};
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
  app.add_option("--order", c.order, "polynomial order 1..4 (default: chosen by cross-validation)")->check(CLI::Range(1, 4));
  app.add_option("--max-order", c.fit.max_polynomial_order, "highest order cross-validation tries")
      ->capture_default_str()
      ->check(CLI::Range(1, 4));
  app.add_flag("--rate-term", c.fit.temperature_rate_term, "fit the dynamic-regime term in dT/dt (bias)");
  app.add_flag("--scale-factor-rate-term", c.fit.scale_factor_rate_term,
               "also a dT/dt term in the scale factor (needs opposite orientations during ramps)");
  app.add_flag("--no-scale-factor", c.no_scale_factor, "fit the bias only (one orientation is enough)");
  app.add_flag("--gyro-scale-factor", c.fit.gyro_scale_factor,
               "fit gyro scale factor from the Earth rate (navigation-grade gyros only)");
  app.add_option("--reference-temperature-c", c.fit.reference_temperature_c, "temperature the model corrects to")
      ->capture_default_str();
  app.add_option("--window-s", c.windows.window_s, "averaging window [s]")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--rate-window-s", c.windows.rate_window_s, "window of the dT/dt estimate [s]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--max-temperature-age-s", c.windows.max_temperature_age_s,
                 "farthest a thermosensor reading may be from an IMU stamp [s]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--static-gyro-std-rad-s", c.windows.static_angular_rate_std_rad_s, "static-window threshold")
      ->capture_default_str();
  app.add_option("--static-accel-std-m-s2", c.windows.static_specific_force_std_m_s2, "static-window threshold")
      ->capture_default_str();
  app.add_option("--latitude-deg", c.latitude_deg, "test site latitude (gravity and Earth rate)")->capture_default_str();
  app.add_option("--height-m", c.height_m, "test site height")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  if (c.order > 0) c.fit.polynomial_order = c.order;
  if (c.no_scale_factor) c.fit.accelerometer_scale_factor = c.fit.gyro_scale_factor = false;
  c.fit.second_sensor_term = !c.topics.second_temperature.empty();
  c.fit.earth.latitude_rad = c.latitude_deg * kRadPerDeg;
  c.fit.earth.gravity_m_s2 = imu_lab::emulator::normal_gravity_m_s2(imu_lab::emulator::EarthModel::kWgs84Rotating,
                                                                     c.fit.earth.latitude_rad, c.height_m);
  if (c.csv_path.empty()) c.csv_path = default_csv_path(c.out_path);

  return imu_lab::run_tool_main("fit_thermal", [&] {
    const auto data = imu_lab::ros_io::read_thermal_windows(c.recording.recording(), c.topics, c.windows);
    std::printf("fit_thermal: %s, %s\n", c.recording.recording().name().c_str(),
                imu_lab::ros_io::describe_time_window(c.recording.window).c_str());
    std::printf("fit_thermal: %zu IMU samples on %s, %zu temperature readings, %zu windows of %.6g s\n",
                data.imu_messages, data.imu_topic.c_str(), data.temperature_messages, data.windows.size(),
                c.windows.window_s);
    const auto result = imu_lab::thermal::fit_thermal_model(data.windows, c.windows.rate_window_s, c.fit);
    print_summary(result);
    imu_lab::thermal::save_thermal_model(c.out_path, result.model, &result);
    imu_lab::thermal::write_thermal_residual_csv(c.csv_path, result);
    std::printf("fit_thermal: wrote %s and %s\n", c.out_path.c_str(), c.csv_path.c_str());
    if (!c.plot_path.empty()) plot(c.csv_path, c.plot_path);
    return 0;
  });
}
