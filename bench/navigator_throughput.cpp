// Strapdown navigator throughput on increments (samples per second) against the emulator's
// generation rate, measured in one run on the same samples: can the navigator keep up with
// whatever produces its input, and by how much?
//   bench/navigator_throughput [samples (default 2000000)]   (build with -DIMU_LAB_BENCHMARKS=ON)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/static_motion.h"
#include "imu_lab/nav/navigator.h"
#include "imu_lab/ros_io/node/config_paths.h"

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const long samples = argc > 1 ? std::atol(argv[1]) : 2000000;
  using namespace imu_lab;
  const auto profile = emulator::load_sensor_profile(ros_io::resolve_config("sensors", "rlg_navigation"));
  const auto scenario = emulator::load_scenario(ros_io::resolve_config("scenarios", "static"));
  emulator::EmulatorSettings settings;
  settings.rate_hz = 200.0;
  emulator::ImuEmulator emulator(profile, scenario, settings);

  std::vector<nav::ImuIncrement> increments(samples);
  const auto generation_start = std::chrono::steady_clock::now();
  for (auto& increment : increments) {
    const emulator::EmulatedSample sample = emulator.next();
    increment.delta_angle_rad = sample.delta_angle_rad;
    increment.delta_velocity_m_s = sample.delta_velocity_m_s;
    increment.dt_s = emulator.sample_interval_s();
  }
  const double generation_s = seconds_since(generation_start);

  nav::NavigatorConfig config;
  config.vertical.fixed_reference_height_m = scenario.height_m;  // a free vertical channel diverges
  nav::Navigator navigator(config);
  nav::NavState initial;
  initial.q_body_to_enu =
      emulator::attitude_from_roll_pitch_yaw(scenario.roll_rad, scenario.pitch_rad, scenario.yaw_rad);
  initial.latitude_rad = scenario.latitude_rad;
  initial.longitude_rad = scenario.longitude_rad;
  initial.height_m = scenario.height_m;
  navigator.initialise(initial);
  const auto navigation_start = std::chrono::steady_clock::now();
  for (const auto& increment : increments) navigator.update(increment);
  const double navigation_s = seconds_since(navigation_start);

  const double generation_rate = samples / generation_s;
  const double navigation_rate = samples / navigation_s;
  std::printf("navigator_throughput: %ld samples (%.0f s of %s at %.0f Hz)\n", samples, samples / settings.rate_hz,
              profile.name.c_str(), settings.rate_hz);
  std::printf("  emulator generation: %12.0f samples/s\n", generation_rate);
  std::printf("  navigator update:    %12.0f samples/s (%.0fx real time at %.0f Hz)\n", navigation_rate,
              navigation_rate / settings.rate_hz, settings.rate_hz);
  std::printf("  navigator / emulator: %.2f\n", navigation_rate / generation_rate);
  // Keeps the loop from being optimised away and shows the run is sane (held at the scenario's).
  std::printf("  final height %.3f m (scenario %.3f m)\n", navigator.state().height_m, scenario.height_m);
  return 0;
}
