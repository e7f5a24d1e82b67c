// What the noise model costs: one hour of 400 Hz IMU data written to a bag with every noise
// process on, against the same number of messages with no noise at all, measured in one run.
// Build with -DIMU_LAB_BENCHMARKS=ON; run: emulate_noise_cost [tactical_mems.yaml] [out_dir]
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/ros_io/bag/emulated_bag.h"

namespace {

using imu_lab::emulator::TriadErrorModel;

// Every process the emulator offers, on every axis, on top of the profile's own.
void switch_every_process_on(TriadErrorModel& triad, double unit) {
  for (auto& axis : triad.noise_per_axis) {
    axis.push_back(imu_lab::noise::MarkovParameters{1e-4 * unit, 0.5});
    axis.push_back(imu_lab::noise::MarkovParameters{2e-5 * unit, 30.0});
    axis.push_back(imu_lab::noise::SinusoidParameters{1e-4 * unit, 0.7, 0.1});
    axis.push_back(imu_lab::noise::RateRampParameters{1e-8 * unit});
    axis.push_back(imu_lab::noise::WhiteAngleParameters{0.0, 1e-6 * unit});
    axis.push_back(imu_lab::noise::ZeroDcFamilyParameters{2, 1e-9 * unit * unit, 0.01});
  }
}

void clear_every_process(TriadErrorModel& triad) {
  for (auto& axis : triad.noise_per_axis) axis.clear();
  triad.pulse_weight = 0.0;
  triad.bandwidth_hz = 0.0;
  triad.bias_turn_on_sigma.setZero();
}

struct Cost {
  double wall_s = 0.0;
  double cpu_s = 0.0;  // user + system of this process: steadier than wall time on a busy machine
};

double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

Cost cost_to_write(const imu_lab::emulator::SensorProfile& profile, const std::string& path) {
  const auto scenario = imu_lab::emulator::ScenarioConfig{};
  imu_lab::emulator::EmulatorSettings settings;
  settings.rate_hz = 400.0;
  settings.start_time_s = 1.0e9;
  imu_lab::emulator::ImuEmulator emulator(profile, scenario, settings);
  imu_lab::ros_io::EmulatedBagOptions options;
  options.duration_s = 3600.0;
  const auto started = std::chrono::steady_clock::now();
  const double cpu_started_s = cpu_seconds();
  imu_lab::ros_io::write_emulated_bag(emulator, options, path);
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(),
          cpu_seconds() - cpu_started_s};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string profile_path = argc > 1 ? argv[1] : "config/sensors/tactical_mems.yaml";
  const std::string out_dir = argc > 2 ? argv[2] : "/tmp";
  const auto base = imu_lab::emulator::load_sensor_profile(profile_path);

  auto noisy_profile = base;
  switch_every_process_on(noisy_profile.gyro, 1.0);
  switch_every_process_on(noisy_profile.accelerometer, 10.0);
  auto quiet_profile = base;
  clear_every_process(quiet_profile.gyro);
  clear_every_process(quiet_profile.accelerometer);

  const Cost quiet = cost_to_write(quiet_profile, out_dir + "/bench_quiet.bag");
  const Cost noisy = cost_to_write(noisy_profile, out_dir + "/bench_noisy.bag");
  std::printf("one hour at 400 Hz (1.44 M samples, 4 topics each) written to a bag:\n");
  std::printf("  %-24s %9s %9s %12s\n", "", "wall [s]", "cpu [s]", "x real time");
  std::printf("  %-24s %9.2f %9.2f %12.0f\n", "no noise", quiet.wall_s, quiet.cpu_s, 3600.0 / quiet.wall_s);
  std::printf("  %-24s %9.2f %9.2f %12.0f\n", "every noise process on", noisy.wall_s, noisy.cpu_s,
              3600.0 / noisy.wall_s);
  std::printf("  ratio noisy / quiet: %.2f (wall), %.2f (cpu)\n", noisy.wall_s / quiet.wall_s,
              noisy.cpu_s / quiet.cpu_s);
  return 0;
}
