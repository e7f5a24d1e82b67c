// Streaming Allan engine throughput without a bag: one hour of six-channel 400 Hz samples
// (1.44 M, tactical-MEMS-like: offsets, white rate noise, a slow rate random walk), generated in
// memory first, then pushed through the engine with the default options (tau up to 1e4 s, exact
// up to m = 1000). Prints the engine's CPU time (getrusage, this thread only matters: the program
// is single-threaded) and wall time per six-channel sample and samples per second, for the
// per-sample push() and for push_block() in the allan tool's batches of 4096. Not a test.
//   bench/allan_streaming_throughput [seconds=3600] [rate_hz=400] [exact_max_averaging_factor=1000]
//                                    [paths=both|block|sample]
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "imu_lab/allan/streaming_allan.h"

namespace {

constexpr std::size_t kChannels = 6;
constexpr std::size_t kToolBatchSamples = 4096;  // what src/ros_io/bag/allan_bag_pass.cpp queues

struct Recording {
  std::vector<std::int64_t> stamps_ns;
  std::vector<double> values;  // row-major, kChannels per sample
};

Recording emulate(std::size_t sample_count, double rate_hz) {
  const double offsets[kChannels] = {2e-4, -1e-4, 5e-5, 0.05, -0.08, 9.81};
  const double white[kChannels] = {2e-3, 2e-3, 2e-3, 1e-2, 1e-2, 1e-2};
  const double walk[kChannels] = {1e-6, 1e-6, 1e-6, 5e-6, 5e-6, 5e-6};
  std::mt19937_64 generator(1);
  std::normal_distribution<double> normal;
  Recording recording;
  recording.stamps_ns.resize(sample_count);
  recording.values.resize(sample_count * kChannels);
  double bias[kChannels] = {};
  const double period_ns = 1e9 / rate_hz;
  for (std::size_t k = 0; k < sample_count; ++k) {
    recording.stamps_ns[k] = static_cast<std::int64_t>(static_cast<double>(k) * period_ns);
    for (std::size_t c = 0; c < kChannels; ++c) {
      bias[c] += walk[c] * normal(generator);
      recording.values[k * kChannels + c] = offsets[c] + bias[c] + white[c] * normal(generator);
    }
  }
  return recording;
}

double thread_cpu_s() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

template <typename PushAll>
void time_engine(const char* how, std::size_t sample_count, PushAll push_all) {
  const double cpu_before = thread_cpu_s();
  const auto wall_before = std::chrono::steady_clock::now();
  push_all();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_before).count();
  const double cpu_s = thread_cpu_s() - cpu_before;
  const double samples = static_cast<double>(sample_count);
  std::printf("%-28s CPU %6.3f s (%.3f us/sample, %.2f M samples/s)   wall %6.3f s (%.3f us/sample)\n", how, cpu_s,
              1e6 * cpu_s / samples, samples / cpu_s * 1e-6, wall_s, 1e6 * wall_s / samples);
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 3600.0;
  const double rate_hz = argc > 2 ? std::atof(argv[2]) : 400.0;
  imu_lab::allan::StreamingOptions options;
  options.channel_count = kChannels;
  if (argc > 3) options.exact_max_averaging_factor = std::atoi(argv[3]);
  const std::string paths = argc > 4 ? argv[4] : "both";
  const bool time_per_sample = paths != "block";
  const bool time_blocked = paths != "sample";
  const std::size_t sample_count = static_cast<std::size_t>(seconds * rate_hz);
  const Recording recording = emulate(sample_count, rate_hz);
  std::printf("%zu six-channel samples at %.0f Hz, exact up to m = %d, tau up to %.0f s\n", sample_count, rate_hz,
              options.exact_max_averaging_factor, options.max_tau_s);

  imu_lab::allan::StreamingAllan per_sample(options);
  if (time_per_sample)
    time_engine("push (one sample a call)", sample_count, [&] {
      for (std::size_t k = 0; k < sample_count; ++k) {
        per_sample.push(recording.stamps_ns[k], &recording.values[k * kChannels], kChannels);
      }
    });
  imu_lab::allan::StreamingAllan blocked(options);
  if (time_blocked)
    time_engine("push_block (4096 a call)", sample_count, [&] {
      for (std::size_t first = 0; first < sample_count; first += kToolBatchSamples) {
        const std::size_t count = std::min(kToolBatchSamples, sample_count - first);
        blocked.push_block(&recording.stamps_ns[first], &recording.values[first * kChannels], count);
      }
    });
  if (!time_per_sample || !time_blocked) return 0;
  // Both paths must give the same curves, bit for bit (the engine's blocks do not depend on how
  // samples are handed over): a cheap guard against a broken block path.
  const imu_lab::allan::StreamingSnapshot per_sample_result = per_sample.snapshot();
  const imu_lab::allan::StreamingSnapshot blocked_result = blocked.snapshot();
  const auto& a = per_sample_result.curve(imu_lab::allan::Statistic::kModifiedAllan, 5);
  const auto& b = blocked_result.curve(imu_lab::allan::Statistic::kModifiedAllan, 5);
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    worst = std::max(worst, std::abs(a[i].deviation - b[i].deviation) / a[i].deviation);
  }
  std::printf("MDEV points %zu / %zu, max relative difference push vs push_block %.2e\n", a.size(), b.size(), worst);
  return 0;
}
