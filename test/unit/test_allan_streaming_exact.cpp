// Streaming equals the batch reference (to 1e-9 relative) for every statistic up to the exact
// limit, on white + random-walk + flicker-like rates with a large offset.
#include <gtest/gtest.h>

#include "allan_streaming_test_support.h"

namespace imu_lab {
namespace allan {
namespace {

using namespace testing_support;

TEST(AllanStreamingExact, EveryStatisticEqualsBatchUpToTheExactLimit) {
  const StreamingOptions options = test_options(3, 300, 12, 1e3);
  const std::size_t count = 12000;
  const std::vector<std::vector<double>> rates = {synthetic_rate(count, 11), synthetic_rate(count, 12, 9.81),
                                                  synthetic_rate(count, 13, -3e-4)};
  StreamingAllan engine(options);
  feed(engine, rates, 0, count);
  const StreamingSnapshot snapshot = engine.snapshot();

  double worst = 0.0;
  for (const Statistic statistic : kStreamingStatistics) {
    for (std::size_t c = 0; c < rates.size(); ++c) {
      const auto streamed = points_up_to(snapshot.curve(statistic, c), options.exact_max_averaging_factor);
      ASSERT_GE(streamed.size(), 20u) << statistic_name(statistic);
      const auto reference = evaluate_frequency(statistic, rates[c], 1e-3, factors_of(streamed));
      worst =
          std::max(worst, compare_points(streamed, reference, statistic_name(statistic) + " ch" + std::to_string(c)));
    }
  }
  RecordProperty("max_relative_difference", std::to_string(worst));
  std::printf("max relative difference to batch up to m_exact: %.3g\n", worst);
}

TEST(AllanStreamingExact, EveryMSpacingCoversEachFactor) {
  StreamingOptions options = test_options(1, 64, 10, 0.1);
  options.tau_spacing = TauSpacing::kEveryM;
  const std::size_t count = 3000;
  const std::vector<std::vector<double>> rates = {synthetic_rate(count, 5)};
  StreamingAllan engine(options);
  feed(engine, rates, 0, count);
  const auto streamed = points_up_to(engine.snapshot().curve(Statistic::kOverlappingHadamard, 0), 64);
  ASSERT_EQ(streamed.size(), 64u);
  for (int m = 1; m <= 64; ++m) EXPECT_EQ(streamed[m - 1].averaging_factor, m);
  compare_points(streamed, evaluate_frequency(Statistic::kOverlappingHadamard, rates[0], 1e-3, factors_of(streamed)),
                 "ohdev every m");
}

TEST(AllanStreamingExact, SnapshotDuringWarmUpUsesWhatHasArrived) {
  const StreamingOptions options = test_options(1, 100, 10, 1.0);
  const std::vector<std::vector<double>> rates = {synthetic_rate(600, 7, 4.0)};
  StreamingAllan engine(options);
  EXPECT_FALSE(engine.snapshot().warmed_up);  // nothing yet: no tau0
  feed(engine, rates, 0, 600);                // warm-up window is 1000 samples
  ASSERT_FALSE(engine.warmed_up());
  const StreamingSnapshot snapshot = engine.snapshot();
  ASSERT_TRUE(snapshot.warmed_up);
  for (const Statistic statistic : kStreamingStatistics) {
    const auto streamed = points_up_to(snapshot.curve(statistic, 0), options.exact_max_averaging_factor);
    ASSERT_GE(streamed.size(), 10u);
    compare_points(streamed, evaluate_frequency(statistic, rates[0], 1e-3, factors_of(streamed)),
                   statistic_name(statistic) + " during warm-up");
  }
  EXPECT_FALSE(engine.warmed_up());  // the snapshot worked on a copy
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
