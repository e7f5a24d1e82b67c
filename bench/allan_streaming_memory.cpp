// Streaming Allan footprint and throughput for a long IMU run: six channels at 1 kHz, tau up to
// 1e4 s, default options. Prints state_size_bytes() after warm-up, every simulated hour and at
// the end, plus the process's peak resident set, and checks the accuracy of the running sums after
// the whole run against an independent long-double OAVAR of the accelerometer z channel (offset
// 9.81) at a few m. Not a test: run by hand.
//   bench/allan_streaming_memory [hours=24] [rate_hz=1000] [exact_max_averaging_factor=1000]
#include <sys/resource.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "imu_lab/allan/streaming_allan.h"

namespace {

constexpr std::array<int, 3> kCheckedFactors = {1, 10, 1000};

// Overlapping Allan sums in long double from the same values minus the same offset.
class LongDoubleAllan {
 public:
  void add(double value, double offset) {
    phase_ += static_cast<long double>(value) - offset;
    ++count_;
    ring_[count_ % ring_.size()] = phase_;
    for (std::size_t i = 0; i < kCheckedFactors.size(); ++i) {
      const long long m = kCheckedFactors[i];
      if (count_ < 2 * m) continue;
      const long double d = phase_ - 2 * ring_[(count_ - m) % ring_.size()] + ring_[(count_ - 2 * m) % ring_.size()];
      squares_[i] += d * d;
      ++terms_[i];
    }
  }
  double deviation(std::size_t i) const {
    const long double m = kCheckedFactors[i];
    return static_cast<double>(std::sqrt(squares_[i] / (2 * m * m * terms_[i])));
  }

 private:
  std::array<long double, 2 * 1000 + 1> ring_{};
  std::array<long double, 3> squares_{};
  std::array<long long, 3> terms_{};
  long double phase_ = 0.0L;
  long long count_ = 0;
};

// Six IMU-like channels: white noise plus a slow random walk on gravity-sized offsets.
class ImuSignal {
 public:
  explicit ImuSignal(unsigned seed) : generator_(seed) {}
  void next(std::vector<double>& sample) {
    for (int c = 0; c < 6; ++c) {
      random_walk_[c] += 1e-6 * normal_(generator_);
      sample[c] = kOffsets[c] + 1e-3 * normal_(generator_) + random_walk_[c];
    }
  }

 private:
  static constexpr double kOffsets[6] = {1e-4, -2e-4, 5e-5, 0.1, -0.2, 9.81};  // rad/s, m/s^2
  std::mt19937_64 generator_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  double random_walk_[6] = {0, 0, 0, 0, 0, 0};
};

}  // namespace

int main(int argc, char** argv) {
  using imu_lab::allan::StreamingAllan;
  const double hours = argc > 1 ? std::atof(argv[1]) : 24.0;
  const double rate_hz = argc > 2 ? std::atof(argv[2]) : 1000.0;
  imu_lab::allan::StreamingOptions options;  // 6 channels, m_exact 1000, 10 points/decade, tau <= 1e4 s
  if (argc > 3) options.exact_max_averaging_factor = std::atoi(argv[3]);
  StreamingAllan engine(options);
  ImuSignal signal(2024);
  LongDoubleAllan reference;
  double reference_offset = 0.0;

  const long long samples = static_cast<long long>(hours * 3600.0 * rate_hz);
  const long long per_hour = static_cast<long long>(3600.0 * rate_hz);
  const long long period_ns = static_cast<long long>(1e9 / rate_hz);
  const long long warm_up = static_cast<long long>(options.warm_up_sample_count);
  std::vector<double> sample(6);
  const auto start = std::chrono::steady_clock::now();
  std::printf("samples %lld, channels 6, m_exact %d\n", samples, options.exact_max_averaging_factor);
  for (long long k = 0; k < samples; ++k) {
    signal.next(sample);
    engine.push(k * period_ns, sample);
    if (k + 1 > warm_up) {
      reference.add(sample[5], reference_offset);
    } else if (k + 1 == warm_up) {
      std::printf("after warm-up: state %zu bytes\n", engine.state_size_bytes());
      // The offset is fixed only now: replay the warm-up window into the reference.
      reference_offset = engine.snapshot().channels[5].offset;
      ImuSignal replay(2024);
      std::vector<double> replayed(6);
      for (long long j = 0; j <= k; ++j) {
        replay.next(replayed);
        reference.add(replayed[5], reference_offset);
      }
    }
    if ((k + 1) % per_hour == 0) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("hour %lld: state %zu bytes, %.1f s elapsed\n", (k + 1) / per_hour, engine.state_size_bytes(),
                  elapsed);
      std::fflush(stdout);
    }
  }
  const double push_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto snapshot_start = std::chrono::steady_clock::now();
  const imu_lab::allan::StreamingSnapshot snapshot = engine.snapshot();
  const double snapshot_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - snapshot_start).count();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("end: state %zu bytes; peak RSS %ld kB; %.2f us per 6-channel sample; snapshot %.3f s\n",
              engine.state_size_bytes(), usage.ru_maxrss, 1e6 * push_seconds / samples, snapshot_seconds);
  const auto& curve = snapshot.curve(imu_lab::allan::Statistic::kOverlappingAllan, 5);
  if (!curve.empty()) {
    std::printf("accel z OADEV: %zu points, tau %.3g .. %.3g s\n", curve.size(), curve.front().tau_s,
                curve.back().tau_s);
  }
  for (const auto& point : curve) {
    for (std::size_t i = 0; i < kCheckedFactors.size(); ++i) {
      if (point.averaging_factor != kCheckedFactors[i]) continue;
      const double expected = reference.deviation(i);
      std::printf(
          "accel z OADEV m=%d after %lld samples: streamed %.17g, long double %.17g, relative difference %.2e\n",
          kCheckedFactors[i], samples, point.deviation, expected, std::abs(point.deviation - expected) / expected);
    }
  }
  return 0;
}
