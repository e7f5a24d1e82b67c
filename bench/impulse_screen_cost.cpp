// What the impulse screen, the level-shift screen and the output-step detector cost beside the
// streaming Allan engine, in one run on the same samples: one hour of six channels at 400 Hz from
// the emulator (a MEMS-like triad pair at rest, outputs quantised), generated first, then fed (1)
// to the engine alone with push_block in the allan tool's batches, (2) to the impulse screen
// alone, (3) to the level-shift screen alone (in those batches), (4) to the step detector alone.
// Prints the CPU time per sample of each and the ratios to the engine. Not a test.
//   bench/impulse_screen_cost [seconds=3600] [rate_hz=400]
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "imu_lab/allan/impulse_screen.h"
#include "imu_lab/allan/level_shift_screen.h"
#include "imu_lab/allan/output_step.h"
#include "imu_lab/allan/streaming_allan.h"
#include "imu_lab/emulator/sensor_channel.h"

namespace {

constexpr std::size_t kChannels = 6;
constexpr std::size_t kBatchSamples = 4096;  // the allan tool's batches (src/ros_io/bag/allan_bag_pass.cpp)

imu_lab::emulator::TriadErrorModel triad(double white, double step, double rate_hz) {
  imu_lab::emulator::TriadErrorModel model;
  for (auto& axis : model.noise_per_axis) {
    axis.push_back(imu_lab::noise::WhiteRateParameters{white});
    axis.push_back(imu_lab::noise::RandomWalkParameters{white * 1e-2});
  }
  model.pulse_weight = step / rate_hz;
  return model;
}

double cpu_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 3600.0;
  const double rate_hz = argc > 2 ? std::atof(argv[2]) : 400.0;
  const auto count = static_cast<std::size_t>(seconds * rate_hz);
  const double dt_s = 1.0 / rate_hz;
  imu_lab::emulator::TriadChannel gyro(triad(7.3e-4, 8.7266e-4, rate_hz), "gyro", 1);
  imu_lab::emulator::TriadChannel accel(triad(3.4e-3, 0.0326561, rate_hz), "accelerometer", 1);
  const Eigen::Vector3d gravity(0.0, 0.0, 9.80665);
  std::vector<std::int64_t> stamps_ns(count);
  std::vector<double> values(count * kChannels);
  for (std::size_t k = 0; k < count; ++k) {
    stamps_ns[k] = static_cast<std::int64_t>((k + 1) * dt_s * 1e9);
    const Eigen::Vector3d rate = gyro.measure(Eigen::Vector3d::Zero(), gravity, k * dt_s, dt_s);
    const Eigen::Vector3d force = accel.measure(gravity, gravity, k * dt_s, dt_s);
    for (int axis = 0; axis < 3; ++axis) {
      values[k * kChannels + axis] = rate[axis];
      values[k * kChannels + 3 + axis] = force[axis];
    }
  }

  imu_lab::allan::StreamingOptions engine_options;
  engine_options.channel_count = kChannels;
  imu_lab::allan::StreamingAllan engine(engine_options);
  double start = cpu_s();
  for (std::size_t k = 0; k < count; k += kBatchSamples) {
    engine.push_block(&stamps_ns[k], &values[k * kChannels], std::min(kBatchSamples, count - k));
  }
  const auto snapshot = engine.snapshot();
  const double engine_s = cpu_s() - start;

  imu_lab::allan::ImpulseScreen screen{imu_lab::allan::ImpulseScreenOptions()};
  imu_lab::allan::ScreenedSamples passed;
  start = cpu_s();
  for (std::size_t k = 0; k < count; ++k) {
    screen.push(stamps_ns[k], &values[k * kChannels], passed);
    if (passed.size() >= kBatchSamples) passed.clear();
  }
  screen.finish(passed);
  const double screen_s = cpu_s() - start;

  imu_lab::allan::LevelShiftScreen shift_screen{imu_lab::allan::LevelShiftScreenOptions()};
  imu_lab::allan::ScreenedSamples batch;
  imu_lab::allan::ScreenedSamples unshifted;
  start = cpu_s();
  for (std::size_t k = 0; k < count; k += kBatchSamples) {
    const std::size_t size = std::min(kBatchSamples, count - k);
    batch.clear();
    batch.stamps_ns.assign(stamps_ns.begin() + k, stamps_ns.begin() + k + size);
    batch.values.assign(values.begin() + k * kChannels, values.begin() + (k + size) * kChannels);
    shift_screen.push(batch, unshifted);
    unshifted.clear();
  }
  shift_screen.finish(unshifted);
  const double shift_screen_s = cpu_s() - start;

  imu_lab::allan::OutputStepDetector steps(kChannels);
  start = cpu_s();
  for (std::size_t k = 0; k < count; ++k) steps.push(&values[k * kChannels]);
  const double steps_s = cpu_s() - start;

  const double per_sample_us = 1e6 / static_cast<double>(count);
  std::printf("%zu samples of %zu channels (%.0f s at %.0f Hz); %lld events, %lld shifts, %zu OADEV points on gyro x\n",
              count, kChannels, seconds, rate_hz, static_cast<long long>(screen.report().event_count),
              static_cast<long long>(shift_screen.report().event_count),
              snapshot.curve(imu_lab::allan::Statistic::kOverlappingAllan, 0).size());
  std::printf("engine (push_block)    CPU %7.3f s  %.3f us/sample\n", engine_s, engine_s * per_sample_us);
  std::printf("impulse screen         CPU %7.3f s  %.3f us/sample  = %.3f of the engine\n", screen_s,
              screen_s * per_sample_us, screen_s / engine_s);
  std::printf("level-shift screen     CPU %7.3f s  %.3f us/sample  = %.3f of the engine\n", shift_screen_s,
              shift_screen_s * per_sample_us, shift_screen_s / engine_s);
  std::printf("output-step detector   CPU %7.3f s  %.3f us/sample  = %.3f of the engine\n", steps_s,
              steps_s * per_sample_us, steps_s / engine_s);
  return 0;
}
