// Streaming Allan footprint and throughput for a long IMU run: six channels at 1 kHz, tau up to
// 1e4 s, default options. Prints state_size_bytes() after warm-up, every simulated hour and at
// the end, plus the process's peak resident set, and checks the accuracy of the running sums after
// the whole run against an independent long-double OAVAR of the accelerometer z channel (offset
// 9.81) at a few m. Not a test: run by hand.
//   bench/allan_streaming_memory [hours=24] [rate_hz=1000]
#include <sys/resource.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "imu_lab/allan/streaming_allan.h"

int main(int argc, char** argv) {
  using imu_lab::allan::StreamingAllan;
  const double hours = argc > 1 ? std::atof(argv[1]) : 24.0;
  const double rate_hz = argc > 2 ? std::atof(argv[2]) : 1000.0;
  imu_lab::allan::StreamingOptions options;  // 6 channels, m_exact 1000, 10 points/decade, tau <= 1e4 s
  StreamingAllan engine(options);

  std::mt19937_64 generator(2024);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double offsets[6] = {1e-4, -2e-4, 5e-5, 0.1, -0.2, 9.81};  // rad/s, m/s^2
  double random_walk[6] = {0, 0, 0, 0, 0, 0};
  const long long samples = static_cast<long long>(hours * 3600.0 * rate_hz);
  const long long per_hour = static_cast<long long>(3600.0 * rate_hz);
  const long long period_ns = static_cast<long long>(1e9 / rate_hz);
  std::vector<double> sample(6);
  // Long-double reference: phase of channel 5 minus the engine's offset, overlapping Allan sums.
  const std::array<int, 3> checked_factors = {1, 10, 1000};
  std::vector<long double> reference_phase(2 * 1000 + 1, 0.0L);
  std::array<long double, 3> reference_squares = {0.0L, 0.0L, 0.0L};
  std::array<long long, 3> reference_terms = {0, 0, 0};
  long double phase = 0.0L;
  double offset = 0.0;
  const auto start = std::chrono::steady_clock::now();
  std::printf("samples %lld, channels 6, m_exact %d\n", samples, options.exact_max_averaging_factor);
  for (long long k = 0; k < samples; ++k) {
    for (int c = 0; c < 6; ++c) {
      random_walk[c] += 1e-6 * normal(generator);
      sample[c] = offsets[c] + 1e-3 * normal(generator) + random_walk[c];
    }
    engine.push(k * period_ns, sample);
    if (k + 1 == static_cast<long long>(options.warm_up_sample_count)) {
      std::printf("after warm-up: state %zu bytes\n", engine.state_size_bytes());
      offset = engine.snapshot().channels[5].offset;
      // Replay the warm-up window into the reference (same generator, same seed).
      std::mt19937_64 replay(2024);
      std::normal_distribution<double> replay_normal(0.0, 1.0);
      double replay_walk[6] = {0, 0, 0, 0, 0, 0};
      for (long long j = 0; j <= k; ++j) {
        double value = 0.0;
        for (int c = 0; c < 6; ++c) {
          replay_walk[c] += 1e-6 * replay_normal(replay);
          const double v = offsets[c] + 1e-3 * replay_normal(replay) + replay_walk[c];
          if (c == 5) value = v;
        }
        phase += static_cast<long double>(value) - offset;
        reference_phase[(j + 1) % reference_phase.size()] = phase;
        for (std::size_t i = 0; i < checked_factors.size(); ++i) {
          const long long m = checked_factors[i];
          if (j + 1 < 2 * m) continue;
          const long double d = phase - 2 * reference_phase[(j + 1 - m) % reference_phase.size()] +
                                reference_phase[(j + 1 - 2 * m) % reference_phase.size()];
          reference_squares[i] += d * d;
          ++reference_terms[i];
        }
      }
    } else if (k + 1 > static_cast<long long>(options.warm_up_sample_count)) {
      phase += static_cast<long double>(sample[5]) - offset;
      reference_phase[(k + 1) % reference_phase.size()] = phase;
      for (std::size_t i = 0; i < checked_factors.size(); ++i) {
        const long long m = checked_factors[i];
        if (k + 1 < 2 * m) continue;
        const long double d = phase - 2 * reference_phase[(k + 1 - m) % reference_phase.size()] +
                              reference_phase[(k + 1 - 2 * m) % reference_phase.size()];
        reference_squares[i] += d * d;
        ++reference_terms[i];
      }
    }
    if ((k + 1) % per_hour == 0) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("hour %lld: state %zu bytes, %.1f s elapsed\n", (k + 1) / per_hour, engine.state_size_bytes(), elapsed);
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
  const auto& curve = snapshot.curve(imu_lab::allan::Statistic::kOverlappingAllan, 0);
  if (!curve.empty()) {
    std::printf("gyro x OADEV: %zu points, tau %.3g .. %.3g s\n", curve.size(), curve.front().tau_s, curve.back().tau_s);
  }
  for (const auto& point : snapshot.curve(imu_lab::allan::Statistic::kOverlappingAllan, 5)) {
    for (std::size_t i = 0; i < checked_factors.size(); ++i) {
      if (point.averaging_factor != checked_factors[i] || reference_terms[i] == 0) continue;
      const long double m = checked_factors[i];
      const double reference = static_cast<double>(std::sqrt(reference_squares[i] / (2 * m * m * reference_terms[i])));
      std::printf("accel z OADEV m=%d after %lld samples: streamed %.17g, long double %.17g, relative difference %.2e\n",
                  checked_factors[i], samples, point.deviation, reference,
                  std::abs(point.deviation - reference) / reference);
    }
  }
  return 0;
}
