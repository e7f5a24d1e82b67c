// Memory is bounded independently of run length: 24 hours of six-channel 1 kHz data (86.4 M
// samples) leave the engine's own footprint exactly where it was after warm-up, and the process's
// resident set flat once the longest window has filled. The samples come from a cheap
// deterministic generator through push_block, not from the emulator, so that the run fits in a
// test (the emulator's cost would dominate); bench/allan_emulated_memory does the 24 h through the
// real emulator with the engine's default options.
// Under ASan/UBSan the run is cut to 2 h: that step looks for memory errors, not for the figure.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "allan_streaming_test_support.h"

#if defined(__SANITIZE_ADDRESS__)
#define IMU_LAB_SANITIZED_BUILD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define IMU_LAB_SANITIZED_BUILD 1
#endif
#endif

namespace imu_lab {
namespace allan {
namespace {

using namespace testing_support;

#ifdef IMU_LAB_SANITIZED_BUILD
constexpr int kRunHours = 2;
#else
constexpr int kRunHours = 24;
#endif
constexpr std::int64_t kSamplesPerHour = 3600LL * 1000;  // 1 kHz
constexpr std::size_t kChannels = 6;
constexpr std::size_t kBlockSamples = 4000;  // divides an hour

// xorshift64*: a few nanoseconds per value, so the engine's cost dominates the run.
class CheapImuSignal {
 public:
  // Uniform noise of half-width 1e-3 on gravity-sized offsets, one block of samples row-major.
  void fill(std::vector<double>& values) {
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = kOffsets[i % kChannels] + 1e-3 * uniform();
  }

 private:
  double uniform() {  // in [-1, 1)
    state_ ^= state_ >> 12;
    state_ ^= state_ << 25;
    state_ ^= state_ >> 27;
    return static_cast<double>((state_ * 2685821657736338717ULL) >> 11) * 0x1.0p-52 - 1.0;
  }
  static constexpr double kOffsets[kChannels] = {1e-4, -2e-4, 5e-5, 0.1, -0.2, 9.81};  // rad/s, m/s^2
  std::uint64_t state_ = 0x9E3779B97F4A7C15ULL;
};

std::size_t resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t total_pages = 0, resident_pages = 0;
  statm >> total_pages >> resident_pages;
  return resident_pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

TEST(AllanStreamingMemory, FootprintStaysFlatOverTwentyFourHoursOfSixChannels) {
  StreamingOptions options;                 // six channels, tau up to 1e4 s: the whole pyramid exists
  options.exact_max_averaging_factor = 64;  // few taus per level keeps the test fast
  options.points_per_decade = 2;
  StreamingAllan engine(options);
  CheapImuSignal signal;
  std::vector<std::int64_t> stamps_ns(kBlockSamples);
  std::vector<double> values(kBlockSamples * kChannels);
  std::size_t state_after_warm_up = 0;
  std::vector<std::size_t> state_hourly, resident_hourly;
  for (std::int64_t first = 0; first < kRunHours * kSamplesPerHour; first += kBlockSamples) {
    for (std::size_t k = 0; k < kBlockSamples; ++k) stamps_ns[k] = (first + k) * kMillisecondNs;
    signal.fill(values);
    engine.push_block(stamps_ns.data(), values.data(), kBlockSamples);
    if (state_after_warm_up == 0 && engine.warmed_up()) state_after_warm_up = engine.state_size_bytes();
    if ((first + kBlockSamples) % kSamplesPerHour == 0) {
      state_hourly.push_back(engine.state_size_bytes());
      resident_hourly.push_back(resident_bytes());
    }
  }
  ASSERT_GT(state_after_warm_up, 0u);
  ASSERT_EQ(state_hourly.size(), static_cast<std::size_t>(kRunHours));
  for (const std::size_t bytes : state_hourly) EXPECT_EQ(bytes, state_after_warm_up);
  // The resident set may still grow while the top pyramid level's window first fills (its pages
  // are reserved at warm-up and touched as points arrive); over the second half it must not.
  const std::size_t half = resident_hourly.size() / 2;
  const long long growth_bytes = static_cast<long long>(resident_hourly.back()) - resident_hourly[half - 1];
  EXPECT_LE(growth_bytes, 256 * 1024) << "resident set grew over the second half of the run";

  const StreamingSnapshot snapshot = engine.snapshot();
  const auto& curve = snapshot.curve(Statistic::kOverlappingAllan, 5);
  ASSERT_FALSE(curve.empty());
  EXPECT_GE(curve.back().tau_s, 1000.0);  // the longest taus really were reached
  std::printf(
      "%d h of 6 channels at 1 kHz (%lld samples): engine state %zu bytes after warm-up and every hour;\n"
      "resident set after hour 1 %.1f MB, hour %zu %.1f MB, hour %d %.1f MB; longest tau %.0f s\n",
      kRunHours, kRunHours * kSamplesPerHour, state_after_warm_up, resident_hourly.front() / 1e6, half,
      resident_hourly[half - 1] / 1e6, kRunHours, resident_hourly.back() / 1e6, curve.back().tau_s);
  EXPECT_LT(state_after_warm_up, 100u * 1000 * 1000);
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
