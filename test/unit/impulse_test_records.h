// Shared by the impulse-screen tests: emulated six-channel static records shaped like a MEMS IMU
// at rest (low-passed white noise, rate random walk, outputs quantised, the accelerometer's LSB
// about its noise; no bias instability: its Markov bank would cost most of the emulation and
// moves the level far slower than the screen looks), knocks to inject into them, and the screen and engine run
// over a record.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <cstdint>
#include <vector>

#include "imu_lab/allan/impulse_screen.h"
#include "imu_lab/allan/streaming_allan.h"
#include "imu_lab/emulator/sensor_channel.h"

namespace imu_lab {
namespace impulse_test {

constexpr std::size_t kChannels = 6;
constexpr std::int64_t kStartNs = 1000000000;  // 1 s: stamps are positive like ROS times

struct Record {
  double rate_hz = 0.0;
  std::vector<std::int64_t> stamps_ns;
  std::vector<double> values;  // row-major, kChannels per sample
  std::size_t size() const { return stamps_ns.size(); }
  double& at(std::size_t sample, std::size_t channel) { return values[sample * kChannels + channel]; }
  double at(std::size_t sample, std::size_t channel) const { return values[sample * kChannels + channel]; }
  double time_s(std::size_t sample) const { return (stamps_ns[sample] - kStartNs) * 1e-9; }
};

// A triad carrying the same noise on every axis, its output quantised to `step` in rate.
inline emulator::TriadErrorModel mems_triad(double white_density, double random_walk, double bandwidth_hz, double step,
                                            double rate_hz) {
  emulator::TriadErrorModel model;
  for (auto& axis : model.noise_per_axis) {
    axis.push_back(noise::WhiteRateParameters{white_density});
    axis.push_back(noise::RandomWalkParameters{random_walk});
  }
  model.bandwidth_hz = bandwidth_hz;
  model.pulse_weight = step / rate_hz;  // whole pulses per sample: the rate is a multiple of step
  return model;
}

// Gyro: 2.5 deg/sqrt(h) behind a 30 Hz low-pass, 0.05 deg/s LSB (about a tenth of its noise at
// 100 Hz); accelerometer: 3.5 mg/sqrt(Hz), 3.33 mg LSB (about its noise at 100 Hz); 1 g on z.
inline Record emulate_static_record(double duration_s, double rate_hz, std::uint64_t seed) {
  const double dt_s = 1.0 / rate_hz;
  emulator::TriadChannel gyro(mems_triad(7.3e-4, 2.0e-6, 30.0, 8.7266e-4, rate_hz), "gyro", seed);
  emulator::TriadChannel accel(mems_triad(3.4e-3, 1.0e-5, 0.0, 0.0326561, rate_hz), "accelerometer", seed);
  const Eigen::Vector3d gravity(0.0, 0.0, 9.80665);
  Record record;
  record.rate_hz = rate_hz;
  const auto count = static_cast<std::size_t>(duration_s * rate_hz);
  record.stamps_ns.reserve(count);
  record.values.reserve(count * kChannels);
  for (std::size_t k = 0; k < count; ++k) {
    record.stamps_ns.push_back(kStartNs + static_cast<std::int64_t>(std::llround((k + 1) * dt_s * 1e9)));
    const Eigen::Vector3d rate = gyro.measure(Eigen::Vector3d::Zero(), gravity, k * dt_s, dt_s);
    const Eigen::Vector3d force = accel.measure(gravity, gravity, k * dt_s, dt_s);
    for (int axis = 0; axis < 3; ++axis) record.values.push_back(rate[axis]);
    for (int axis = 0; axis < 3; ++axis) record.values.push_back(force[axis]);
  }
  return record;
}

// The screens' clean records: two hours at 100 Hz (seed 1) and one at 400 Hz (seed 2), each handed
// to `check` with a description of it.
template <typename Check>
void for_each_clean_record(Check check) {
  struct Case {
    double rate_hz;
    double duration_s;
    std::uint64_t seed;
  };
  for (const Case& run : {Case{100.0, 7200.0, 1}, Case{400.0, 3600.0, 2}}) {
    check(emulate_static_record(run.duration_s, run.rate_hz, run.seed),
          std::to_string(run.rate_hz) + " Hz, seed " + std::to_string(run.seed));
  }
}

// Per channel the standard deviation of one sample's difference from the previous one, over
// sqrt(2): the noise scale knocks are sized by.
inline std::array<double, kChannels> sample_noise(const Record& record) {
  std::array<double, kChannels> sigma{};
  for (std::size_t c = 0; c < kChannels; ++c) {
    double sum = 0.0;
    for (std::size_t k = 1; k < record.size(); ++k) {
      const double difference = record.at(k, c) - record.at(k - 1, c);
      sum += difference * difference;
    }
    sigma[c] = std::sqrt(sum / (2.0 * (record.size() - 1)));
  }
  return sigma;
}

// A knock at time_s: per channel a ringing of peak_sigma[c] noise scales (cosine at ringing_hz,
// decaying with decay_s, starting at its peak) and a lasting bias step of step_sigma[c] scales.
struct Knock {
  double time_s = 0.0;
  std::array<double, kChannels> peak_sigma{};
  std::array<double, kChannels> step_sigma{};
  double ringing_hz = 15.0;
  double decay_s = 0.08;
};

inline void inject(Record& record, const Knock& knock, const std::array<double, kChannels>& sigma) {
  for (std::size_t k = 0; k < record.size(); ++k) {
    const double t = record.time_s(k) - knock.time_s;
    if (t < 0.0) continue;
    const double ringing = std::exp(-t / knock.decay_s) * std::cos(2.0 * M_PI * knock.ringing_hz * t);
    for (std::size_t c = 0; c < kChannels; ++c) {
      record.at(k, c) += sigma[c] * (knock.step_sigma[c] + knock.peak_sigma[c] * ringing);
    }
  }
}

struct ScreenRun {
  allan::ImpulseScreenReport report;
  allan::ScreenedSamples passed;
};

inline ScreenRun screen(const Record& record, allan::ImpulseScreenOptions options = allan::ImpulseScreenOptions()) {
  allan::ImpulseScreen impulse_screen(options);
  ScreenRun run;
  for (std::size_t k = 0; k < record.size(); ++k) {
    impulse_screen.push(record.stamps_ns[k], &record.values[k * kChannels], run.passed);
  }
  impulse_screen.finish(run.passed);
  run.report = impulse_screen.report();
  return run;
}

inline allan::StreamingOptions engine_options(double confidence = 0.683) {
  allan::StreamingOptions options;
  options.channel_count = kChannels;
  options.max_tau_s = 400.0;
  options.confidence = confidence;
  return options;
}

inline allan::StreamingSnapshot engine_snapshot(const std::vector<std::int64_t>& stamps_ns,
                                                const std::vector<double>& values, double confidence = 0.683) {
  allan::StreamingAllan engine(engine_options(confidence));
  engine.push_block(stamps_ns.data(), values.data(), stamps_ns.size());
  return engine.snapshot();
}

// The clean record's OADEV lies within the confidence interval of the screened record's at every
// tau of every channel (each interval at 1 - 0.01 / points: Bonferroni, 99 % family-wise), checked
// here; returns at how many points the unscreened record's OADEV leaves the clean curve's interval
// of the same confidence (same data, same EDF), which shows that the agreement is the screen's.
inline int expect_screened_curve_like_clean(const Record& clean, const allan::ScreenedSamples& screened,
                                            const Record& unscreened) {
  const std::size_t points =
      kChannels * engine_snapshot(clean.stamps_ns, clean.values).curve(allan::Statistic::kOverlappingAllan, 0).size();
  const double confidence = 1.0 - 0.01 / static_cast<double>(points);
  const auto reference_snapshot = engine_snapshot(clean.stamps_ns, clean.values, confidence);
  const auto screened_snapshot = engine_snapshot(screened.stamps_ns, screened.values, confidence);
  const auto unscreened_snapshot = engine_snapshot(unscreened.stamps_ns, unscreened.values, confidence);
  int unscreened_outside = 0;
  for (std::size_t c = 0; c < kChannels; ++c) {
    const auto& reference = reference_snapshot.curve(allan::Statistic::kOverlappingAllan, c);
    const auto& after = screened_snapshot.curve(allan::Statistic::kOverlappingAllan, c);
    const auto& before = unscreened_snapshot.curve(allan::Statistic::kOverlappingAllan, c);
    EXPECT_EQ(after.size(), reference.size());
    EXPECT_EQ(before.size(), reference.size());
    for (std::size_t i = 0; i < reference.size() && i < after.size() && i < before.size(); ++i) {
      const auto& point = reference[i];
      EXPECT_GE(point.deviation, after[i].deviation_lower) << "channel " << c << " tau " << point.tau_s;
      EXPECT_LE(point.deviation, after[i].deviation_upper) << "channel " << c << " tau " << point.tau_s;
      if (before[i].deviation < point.deviation_lower || before[i].deviation > point.deviation_upper) {
        ++unscreened_outside;
      }
    }
  }
  std::printf("unscreened: %d of %zu OADEV points outside the clean curve's interval\n", unscreened_outside, points);
  return unscreened_outside;
}

}  // namespace impulse_test
}  // namespace imu_lab
