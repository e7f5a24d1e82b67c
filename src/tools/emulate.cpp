// emulate: sensor profile + scenario -> bag of /imu/raw, /imu/temperature, /imu/truth and
// /imu/increment, faster than real time, bit-identical for the same seed and configuration.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/progress.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "imu_lab/ros_io/bag/emulated_bag.h"

int main(int argc, char** argv) {
  CLI::App app{"Emulate an IMU (error-model profile in a scenario) into a bag."};
  std::string profile_name = "tactical_mems";
  std::string scenario_name = "static";
  std::string out_path;
  double duration_s = 0.0;
  imu_lab::emulator::EmulatorSettings settings;
  settings.rate_hz = 200.0;
  settings.start_time_s = 1.0e9;
  imu_lab::ros_io::EmulatedBagOptions options;
  bool no_truth = false;
  bool no_increments = false;
  app.add_option("--profile", profile_name, "sensor profile: a name in config/sensors/ or a YAML path")
      ->capture_default_str();
  app.add_option("--scenario", scenario_name, "scenario: a name in config/scenarios/ or a YAML path")
      ->capture_default_str();
  app.add_option("-o,--out", out_path, "bag to write")->required();
  using namespace imu_lab::option_range;
  const auto* duration_option =
      app.add_option("--duration-s", duration_s, "length of the run [s] (default: the scenario's duration_s)")
          ->check(positive());
  app.add_option("--rate-hz", settings.rate_hz, "sample rate [Hz]")
      ->capture_default_str()
      ->check(positive())
      ->check(between(0.0, 1e9));  // stamps are whole nanoseconds
  app.add_option("--seed", settings.seed, "random seed")->capture_default_str();
  app.add_option("--start-time-s", settings.start_time_s, "stamp of the start of the first sample [s]")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--frame-id", options.frame_id, "frame_id of the sensor")->capture_default_str();
  app.add_flag("--no-truth", no_truth, "do not write /imu/truth");
  app.add_flag("--no-increments", no_increments, "do not write /imu/increment");
  if (const auto status = imu_lab::parse_tool_options("emulate", app, argc, argv)) return *status;
  options.write_truth = !no_truth;
  options.write_increments = !no_increments;
  options.on_progress = imu_lab::terminal_progress("emulate", "samples");

  return imu_lab::run_tool_main("emulate", [&] {
    const auto profile =
        imu_lab::emulator::load_sensor_profile(imu_lab::ros_io::resolve_config("sensors", profile_name));
    const auto scenario = imu_lab::emulator::load_scenario(imu_lab::ros_io::resolve_config("scenarios", scenario_name));
    options.duration_s = duration_option->count() > 0 ? duration_s : scenario.duration_s;
    if (!(options.duration_s > 0.0)) {
      std::cerr << "emulate: the scenario " << scenario.source << " has no duration_s; give --duration-s\n";
      return 2;
    }
    imu_lab::emulator::ImuEmulator emulator(profile, scenario, settings);
    const auto started = std::chrono::steady_clock::now();
    const auto samples = imu_lab::ros_io::write_emulated_bag(emulator, options, out_path);
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::printf("emulate: wrote %s: %llu samples of %s in %s, %.1f s of data at %.6g Hz in %.2f s (%.0fx real time)\n",
                out_path.c_str(), static_cast<unsigned long long>(samples), profile.name.c_str(), scenario.type.c_str(),
                options.duration_s, settings.rate_hz, wall_s, options.duration_s / std::max(wall_s, 1e-9));
    return 0;
  });
}
