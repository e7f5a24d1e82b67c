// Memory is bounded independently of run length: two hours of six-channel 1 kHz data leave the
// engine's footprint exactly where it was after warm-up. (bench/allan_streaming_memory.cpp gives
// the 24 h figure with the default options.)
#include <gtest/gtest.h>

#include <random>

#include "allan_streaming_test_support.h"

namespace imu_lab {
namespace allan {
namespace {

using namespace testing_support;

TEST(AllanStreamingMemory, FootprintDoesNotGrowOverTwoHoursOfSixChannels) {
  StreamingOptions options;  // six channels, tau up to 1e4 s: the whole pyramid exists
  options.exact_max_averaging_factor = 64;  // few taus per level keeps the test fast
  options.points_per_decade = 2;
  const std::int64_t samples = 2LL * 3600 * 1000;
  std::mt19937_64 generator(81);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  const double offsets[6] = {1e-4, -2e-4, 5e-5, 0.1, -0.2, 9.81};
  StreamingAllan engine(options);
  std::vector<double> sample(6);
  std::size_t after_warm_up = 0;
  std::vector<std::size_t> hourly;
  for (std::int64_t k = 0; k < samples; ++k) {
    for (int c = 0; c < 6; ++c) sample[c] = offsets[c] + 1e-3 * noise(generator);
    engine.push(k * kMillisecondNs, sample);
    if (k == static_cast<std::int64_t>(options.warm_up_sample_count)) after_warm_up = engine.state_size_bytes();
    if ((k + 1) % 3600000 == 0) hourly.push_back(engine.state_size_bytes());
  }
  ASSERT_GT(after_warm_up, 0u);
  for (const std::size_t bytes : hourly) EXPECT_EQ(bytes, after_warm_up);
  const StreamingSnapshot snapshot = engine.snapshot();
  // The longest taus really were reached: the pyramid is not empty at the top.
  const auto& curve = snapshot.curve(Statistic::kOverlappingAllan, 5);
  ASSERT_FALSE(curve.empty());
  EXPECT_GE(curve.back().tau_s, 1000.0);
  std::printf("state after warm-up %zu bytes, after 2 h %zu bytes; longest tau %.0f s\n", after_warm_up,
              hourly.back(), curve.back().tau_s);
  EXPECT_LT(after_warm_up, 100u * 1000 * 1000);
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
