// Gaps, duplicate and out-of-order stamps, NaN/Inf: detected, reported, and handled so that the
// result is the batch statistic pooled over the clean segments.
#include <gtest/gtest.h>

#include "allan_streaming_test_support.h"
#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace allan {
namespace {

using namespace testing_support;

constexpr int kExactLimit = 120;

StreamingOptions small_options(std::size_t channels) { return test_options(channels, kExactLimit, 8, 0.1); }

// Pooled over segments: '#' adds, and the variance is the '#'-weighted mean of the segments'
// variances (for TOTDEV '#' is N - 2, its normaliser; for the dispersions the spread per segment).
void expect_pooled_batch(const std::vector<StabilityPoint>& streamed, const std::vector<std::vector<double>>& segments,
                         Statistic statistic, const std::string& what) {
  ASSERT_GE(streamed.size(), 10u) << what;
  for (const StabilityPoint& point : streamed) {
    long long terms = 0;
    double weighted_variance = 0.0;
    std::size_t samples = 0;
    for (const std::vector<double>& segment : segments) samples += segment.size() + 1;  // phase points
    for (const std::vector<double>& segment : segments) {
      const auto batch = evaluate_frequency(statistic, segment, 1e-3, {point.averaging_factor});
      if (batch.empty()) continue;
      terms += batch[0].term_count;
      weighted_variance += batch[0].term_count * batch[0].deviation * batch[0].deviation;
    }
    const std::string where = what + " " + statistic_name(statistic) + " m=" + std::to_string(point.averaging_factor);
    EXPECT_EQ(point.term_count, terms) << where;
    // One record of all the segments' phase points would hold term_count(samples, m) terms.
    EXPECT_DOUBLE_EQ(point.pooled_term_fraction,
                     std::min(1.0, static_cast<double>(terms) / term_count(statistic, samples, point.averaging_factor)))
        << where;
    EXPECT_LE(relative_difference(point.deviation, std::sqrt(weighted_variance / terms)), 1e-9) << where;
  }
}

TEST(AllanStreamingIrregularInput, GapsSplitTheRunAndTheSegmentsArePooled) {
  const std::vector<std::size_t> lengths = {3000, 4500, 2500};
  const std::vector<double> rate = synthetic_rate(10000, 41, 2.0);
  StreamingAllan engine(small_options(1));
  std::vector<std::vector<double>> segments;
  std::size_t sample = 0;
  std::int64_t stamp_ns = 0;
  std::vector<std::int64_t> gap_stamps;
  for (std::size_t s = 0; s < lengths.size(); ++s) {
    if (s > 0) {
      stamp_ns += 7 * kMillisecondNs;  // 6 samples missing
      gap_stamps.push_back(stamp_ns);
    }
    segments.emplace_back(rate.begin() + sample, rate.begin() + sample + lengths[s]);
    for (std::size_t k = 0; k < lengths[s]; ++k, ++sample) {
      if (k > 0) stamp_ns += kMillisecondNs;
      engine.push(stamp_ns, {rate[sample]});
    }
  }
  const StreamingSnapshot snapshot = engine.snapshot();
  for (const Statistic statistic : kStreamingStatistics) {
    expect_pooled_batch(points_up_to(snapshot.curve(statistic, 0), kExactLimit), segments, statistic, "gaps");
  }
  const TimingReport& timing = snapshot.timing;
  EXPECT_DOUBLE_EQ(timing.tau0_s, 1e-3);
  EXPECT_EQ(timing.gap_count, 2);
  EXPECT_NEAR(timing.gap_time_s, 2 * 6e-3, 1e-12);
  EXPECT_EQ(timing.accepted_sample_count, 10000);
  EXPECT_EQ(snapshot.channels[0].segment_count, 3);
  ASSERT_EQ(timing.events.size(), 2u);
  EXPECT_EQ(timing.events[0].kind, StampEventKind::kGap);
  EXPECT_EQ(timing.events[0].sample_index, 3000);
  EXPECT_EQ(timing.events[0].stamp_ns, gap_stamps[0]);
  EXPECT_EQ(timing.events[0].previous_stamp_ns, gap_stamps[0] - 7 * kMillisecondNs);
  EXPECT_EQ(timing.events[1].sample_index, 7500);
  EXPECT_EQ(timing.interval_max_deviation_s, 0.0);
}

TEST(AllanStreamingIrregularInput, NonFiniteValuesAreExcludedAndSplitOnlyTheirChannel) {
  const std::size_t count = 9000;
  std::vector<std::vector<double>> rates = {synthetic_rate(count, 51), synthetic_rate(count, 52, -1.0)};
  // 500 is inside the warm-up window: it must not reach the offset either.
  const std::vector<std::size_t> bad = {500, 4000, 7000};
  rates[1][500] = std::nan("");
  rates[1][4000] = std::numeric_limits<double>::infinity();
  rates[1][7000] = -std::numeric_limits<double>::infinity();
  StreamingAllan engine(small_options(2));
  feed(engine, rates, 0, count);
  const StreamingSnapshot snapshot = engine.snapshot();

  std::vector<std::vector<double>> clean_pieces;
  std::size_t begin = 0;
  for (const std::size_t index : bad) {
    clean_pieces.emplace_back(rates[1].begin() + begin, rates[1].begin() + index);
    begin = index + 1;
  }
  clean_pieces.emplace_back(rates[1].begin() + begin, rates[1].end());
  for (const Statistic statistic : kStreamingStatistics) {
    expect_pooled_batch(points_up_to(snapshot.curve(statistic, 1), kExactLimit), clean_pieces, statistic,
                        "NaN channel");
    expect_pooled_batch(points_up_to(snapshot.curve(statistic, 0), kExactLimit), {rates[0]}, statistic,
                        "clean channel");
  }
  const ChannelReport& report = snapshot.channels[1];
  EXPECT_EQ(report.non_finite_count, 3);
  EXPECT_EQ(report.first_non_finite_sample_index, 500);
  EXPECT_EQ(report.last_non_finite_sample_index, 7000);
  EXPECT_EQ(report.finite_sample_count, static_cast<std::int64_t>(count) - 3);
  EXPECT_EQ(report.segment_count, 4);
  EXPECT_TRUE(std::isfinite(report.offset));
  EXPECT_EQ(snapshot.channels[0].non_finite_count, 0);
  EXPECT_EQ(snapshot.channels[0].segment_count, 1);
  EXPECT_EQ(snapshot.timing.gap_count, 0);
}

// Finite but absurd values (1e308 rad/s) overflowed the sums to Inf: every later point of the
// channel was lost and the snapshot's noise-type estimate threw (allan_monitor died of it). They
// are now left out like NaN: the channel's curves are those of the clean pieces.
TEST(AllanStreamingIrregularInput, ExtremeFiniteValuesAreExcludedLikeNaN) {
  const std::size_t count = 9000;
  std::vector<std::vector<double>> rates = {synthetic_rate(count, 53), synthetic_rate(count, 54, -1.0)};
  const std::vector<std::size_t> bad = {700, 4000, 4001, 6000};
  rates[1][700] = 1e308;
  rates[1][4000] = -1e308;
  rates[1][4001] = 2e100;
  rates[1][6000] = std::numeric_limits<double>::max();
  StreamingAllan engine(small_options(2));
  feed(engine, rates, 0, count);
  StreamingSnapshot snapshot;
  ASSERT_NO_THROW(snapshot = engine.snapshot());

  std::vector<std::vector<double>> clean_pieces;
  std::size_t begin = 0;
  for (const std::size_t index : bad) {
    if (index > begin) clean_pieces.emplace_back(rates[1].begin() + begin, rates[1].begin() + index);
    begin = index + 1;
  }
  clean_pieces.emplace_back(rates[1].begin() + begin, rates[1].end());
  for (const Statistic statistic : kStreamingStatistics) {
    expect_pooled_batch(points_up_to(snapshot.curve(statistic, 1), kExactLimit), clean_pieces, statistic,
                        "1e308 channel");
    for (const StabilityPoint& point : snapshot.curve(statistic, 1)) {
      EXPECT_TRUE(std::isfinite(point.deviation) && std::isfinite(point.edf)) << statistic_name(statistic);
    }
  }
  EXPECT_EQ(snapshot.channels[1].non_finite_count, 4);
  EXPECT_EQ(snapshot.channels[1].finite_sample_count, static_cast<std::int64_t>(count) - 4);
  EXPECT_LT(std::abs(snapshot.channels[1].offset), 10.0) << "the warm-up's offset left them out too";
  EXPECT_EQ(snapshot.channels[0].non_finite_count, 0);
}

TEST(AllanStreamingIrregularInput, DuplicateAndOutOfOrderSamplesAreDroppedAndReported) {
  const std::size_t count = 6000;
  const std::vector<double> rate = synthetic_rate(count, 61);
  StreamingAllan clean(small_options(1));
  feed(clean, {rate}, 0, count);
  StreamingAllan messy(small_options(1));
  std::int64_t pushed = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const std::int64_t stamp = static_cast<std::int64_t>(k) * kMillisecondNs;
    messy.push(stamp, {rate[k]});
    ++pushed;
    if (k == 2000) {
      messy.push(stamp, {123.0});  // duplicate stamp
      ++pushed;
    }
    if (k == 4000) {
      messy.push(stamp - 3 * kMillisecondNs, {-55.0});  // late sample
      ++pushed;
    }
  }
  const StreamingSnapshot expected = clean.snapshot();
  const StreamingSnapshot snapshot = messy.snapshot();
  for (const Statistic statistic : kStreamingStatistics) {
    compare_points(snapshot.curve(statistic, 0), expected.curve(statistic, 0), statistic_name(statistic));
  }
  const TimingReport& timing = snapshot.timing;
  EXPECT_EQ(timing.input_sample_count, pushed);
  EXPECT_EQ(timing.accepted_sample_count, static_cast<std::int64_t>(count));
  EXPECT_EQ(timing.duplicate_count, 1);
  EXPECT_EQ(timing.out_of_order_count, 1);
  EXPECT_EQ(timing.gap_count, 0);
  ASSERT_EQ(timing.events.size(), 2u);
  EXPECT_EQ(timing.events[0].kind, StampEventKind::kDuplicate);
  EXPECT_EQ(timing.events[0].sample_index, 2001);
  EXPECT_EQ(timing.events[0].stamp_ns, 2000 * kMillisecondNs);
  EXPECT_EQ(timing.events[1].kind, StampEventKind::kOutOfOrder);
  EXPECT_EQ(timing.events[1].sample_index, 4002);
  EXPECT_EQ(timing.events[1].stamp_ns, 3997 * kMillisecondNs);
  EXPECT_EQ(timing.events[1].previous_stamp_ns, 4000 * kMillisecondNs);
}

TEST(AllanStreamingIrregularInput, StopPolicyThrowsNamingTheSample) {
  StreamingOptions options = small_options(1);
  options.stamp_policy = StampPolicy::kStop;
  StreamingAllan engine(options);
  for (int k = 0; k < 1500; ++k) engine.push(k * kMillisecondNs, {1.0});
  try {
    engine.push(1502 * kMillisecondNs, {1.0});
    FAIL() << "a gap under kStop must throw";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("sample 1500"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("gap"), std::string::npos) << error.what();
  }
  EXPECT_THROW(engine.push(1499 * kMillisecondNs, {1.0}), InputError);
  EXPECT_THROW(engine.push(1499 * kMillisecondNs, {1.0, 2.0}), InputError);  // wrong channel count
}

TEST(AllanStreamingIrregularInput, JitterIsReportedAgainstTheMedianInterval) {
  StreamingAllan engine(small_options(1));
  for (int k = 0; k < 4000; ++k) {
    const std::int64_t jitter_ns = (k % 4 == 1) ? 20000 : 0;  // intervals 1.02, 0.98, 1, 1 ms
    engine.push(k * kMillisecondNs + jitter_ns, {0.0});
  }
  const TimingReport timing = engine.snapshot().timing;
  EXPECT_DOUBLE_EQ(timing.tau0_s, 1e-3);
  EXPECT_NEAR(timing.interval_max_deviation_s, 20e-6, 1e-15);
  // 2000 of the 3999 intervals are off by 20 us.
  EXPECT_NEAR(timing.interval_rms_deviation_s, 20e-6 * std::sqrt(2000.0 / 3999.0), 1e-15);
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
