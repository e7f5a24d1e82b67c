// The impulse screen on emulated records: silent on clean data for hours, knocks found with their
// stamps and channels, each one a segment boundary of the engine, and the Allan curve of a
// knocked record after screening that of the clean record within its confidence.
#include "imu_lab/allan/impulse_screen.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "imu_lab/common/config_error.h"
#include "impulse_test_records.h"

namespace imu_lab {
namespace {

using allan::ImpulseEvent;
using allan::ImpulseScreenOptions;
using impulse_test::emulate_static_record;
using impulse_test::inject;
using impulse_test::kChannels;
using impulse_test::Knock;
using impulse_test::kStartNs;
using impulse_test::Record;
using impulse_test::sample_noise;
using impulse_test::screen;

double event_time_s(std::int64_t stamp_ns) { return (stamp_ns - kStartNs) * 1e-9; }

// Per channel the standard deviation of a value's difference from the mean of the `level` before
// it: what the screen's scale estimates (consistently for Gaussian noise).
std::array<double, kChannels> level_deviation_sigma(const Record& record, std::size_t level) {
  std::array<double, kChannels> sigma{};
  for (std::size_t c = 0; c < kChannels; ++c) {
    double window = 0.0;
    for (std::size_t j = 0; j < level; ++j) window += record.at(j, c);
    double sum = 0.0;
    for (std::size_t k = level; k < record.size(); ++k) {
      const double deviation = record.at(k, c) - window / level;
      sum += deviation * deviation;
      window += record.at(k, c) - record.at(k - level, c);
    }
    sigma[c] = std::sqrt(sum / (record.size() - level));
  }
  return sigma;
}

// Three hours of clean data over two seeds and two rates: no event. Gaussian noise passes 12
// scales with probability 3.6e-33 per value, so any event here means a scale far too small --
// as a median absolute deviation of the accelerometers' quantised output gives (their LSB is
// about their noise). The scale itself must be that of the deviation, LSB or not: within 2 % of
// its plain standard deviation (about 20 times the estimate's own sampling error).
TEST(ImpulseScreen, CleanQuantisedRecordsRaiseNoEventForHours) {
  impulse_test::for_each_clean_record([](const Record& record, const std::string& where) {
    const auto result = screen(record);
    EXPECT_EQ(result.report.event_count, 0) << where;
    EXPECT_EQ(result.report.dropped_sample_count, 0);
    EXPECT_EQ(result.passed.size(), record.size());
    EXPECT_EQ(result.passed.stamps_ns, record.stamps_ns);
    EXPECT_EQ(result.passed.values, record.values);
    const auto expected = level_deviation_sigma(record, ImpulseScreenOptions().level_sample_count);
    for (std::size_t c = 0; c < kChannels; ++c) {
      EXPECT_NEAR(result.report.channel_scales[c] / expected[c], 1.0, 0.02)
          << "channel " << c << ", " << where << ": scale " << result.report.channel_scales[c] << ", deviation sigma "
          << expected[c];
    }
  });
}

// One hour at 200 Hz with four disturbances: a knock ringing in accelerometer z and gyro x, a
// knock that leaves a bias step (half a noise scale, as a real knock's 0.2-0.9 mg does), a bias
// step of 25 scales alone, and a one-sample spike.
class KnockedRecord : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    clean_ = new Record(emulate_static_record(3600.0, 200.0, 4));
    knocked_ = new Record(*clean_);
    const auto sigma = sample_noise(*clean_);
    Knock ringing;
    ringing.time_s = 600.0;
    ringing.peak_sigma = {40.0, 0.0, 0.0, 0.0, 0.0, -80.0};
    Knock stepping;
    stepping.time_s = 1500.0;
    stepping.peak_sigma = {30.0, 30.0, 30.0, 30.0, 30.0, 30.0};
    stepping.step_sigma = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    Knock step_only;
    step_only.time_s = 2400.0;
    step_only.step_sigma = {0.0, 25.0, 0.0, 0.0, 0.0, 0.0};
    for (const Knock& knock : {ringing, stepping, step_only}) inject(*knocked_, knock, sigma);
    spike_index_ = static_cast<std::size_t>(3000.0 * 200.0);
    knocked_->at(spike_index_, 3) += 20.0 * sigma[3];
  }
  static void TearDownTestSuite() {
    delete clean_;
    delete knocked_;
  }
  static Record* clean_;
  static Record* knocked_;
  static std::size_t spike_index_;
};
Record* KnockedRecord::clean_ = nullptr;
Record* KnockedRecord::knocked_ = nullptr;
std::size_t KnockedRecord::spike_index_ = 0;

std::vector<std::size_t> channels_of(const ImpulseEvent& event) {
  std::vector<std::size_t> channels;
  for (const auto& peak : event.channels) channels.push_back(peak.channel);
  return channels;
}

TEST_F(KnockedRecord, EveryDisturbanceIsOneEventWithItsStampsAndChannels) {
  const ImpulseScreenOptions options;
  const auto result = screen(*knocked_, options);
  ASSERT_EQ(result.report.event_count, 4);
  ASSERT_EQ(result.report.events.size(), 4u);
  const double sample_s = 1.0 / knocked_->rate_hz;
  const double onsets_s[] = {600.0, 1500.0, 2400.0, knocked_->time_s(spike_index_)};
  for (std::size_t i = 0; i < 4; ++i) {
    const ImpulseEvent& event = result.report.events[i];
    // The first sample at or after the onset is the first over the threshold, and the window
    // reaches guard_before_s before it (to the sample) and guard_after_s past the last flag.
    const double onset_s = onsets_s[i];
    EXPECT_NEAR(event_time_s(event.onset_stamp_ns), onset_s, sample_s) << "event " << i;
    EXPECT_NEAR(event_time_s(event.start_stamp_ns), onset_s - options.guard_before_s, 1.5 * sample_s) << "event " << i;
    EXPECT_GE(event_time_s(event.end_stamp_ns), onset_s + options.guard_after_s) << "event " << i;
    EXPECT_LE(event.peak_stamp_ns, event.end_stamp_ns);
    EXPECT_GE(event.peak_stamp_ns, event.onset_stamp_ns);
    EXPECT_GE(event.flagged_sample_count, 1);
    // Every sample of the window, none outside it.
    const auto dropped = std::count_if(knocked_->stamps_ns.begin(), knocked_->stamps_ns.end(), [&](std::int64_t stamp) {
      return stamp >= event.start_stamp_ns && stamp <= event.end_stamp_ns;
    });
    EXPECT_EQ(event.dropped_sample_count, dropped) << "event " << i;
  }
  // The ringing (cos at 15 Hz decaying over 0.08 s) stays above the threshold for a few tenths of
  // a second: the window ends guard_after_s after its last flagged sample, so it holds it all.
  const ImpulseEvent& ringing = result.report.events[0];
  EXPECT_EQ(channels_of(ringing), (std::vector<std::size_t>{0, 5}));
  EXPECT_EQ(ringing.peak_channel, 5u);
  EXPECT_LT(ringing.peak_sigma, -60.0);  // of the deviation scale, which the level's noise widens
  EXPECT_GT(event_time_s(ringing.end_stamp_ns), 600.0 + 8 * 0.08 + options.guard_after_s - 1.0);
  EXPECT_EQ(channels_of(result.report.events[1]), (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(channels_of(result.report.events[2]), (std::vector<std::size_t>{1}));
  EXPECT_GT(result.report.events[2].peak_sigma, 15.0);
  EXPECT_EQ(channels_of(result.report.events[3]), (std::vector<std::size_t>{3}));
  EXPECT_EQ(result.report.events[3].flagged_sample_count, 1);
  std::int64_t dropped = 0;
  for (const ImpulseEvent& event : result.report.events) dropped += event.dropped_sample_count;
  EXPECT_EQ(result.report.dropped_sample_count, dropped);
  EXPECT_EQ(result.report.passed_sample_count + dropped, static_cast<std::int64_t>(knocked_->size()));
  EXPECT_EQ(result.passed.size() + static_cast<std::size_t>(dropped), knocked_->size());
}

// The hole each event leaves is a gap to the engine: one more segment per event, every channel.
TEST_F(KnockedRecord, TheEngineStartsASegmentAtEveryEvent) {
  const auto result = screen(*knocked_);
  const auto snapshot = impulse_test::engine_snapshot(result.passed.stamps_ns, result.passed.values);
  EXPECT_EQ(snapshot.timing.gap_count, result.report.event_count);
  for (std::size_t c = 0; c < kChannels; ++c) {
    EXPECT_EQ(snapshot.channels[c].segment_count, result.report.event_count + 1) << "channel " << c;
  }
  // Also with a larger gap factor: the windows drop enough samples for it.
  ImpulseScreenOptions options;
  options.guard_before_s = 0.0;
  options.guard_after_s = 0.0;
  options.gap_factor = 40.0;
  const auto narrow = screen(*knocked_, options);
  auto engine_options = impulse_test::engine_options();
  engine_options.gap_factor = options.gap_factor;
  allan::StreamingAllan engine(engine_options);
  engine.push_block(narrow.passed.stamps_ns.data(), narrow.passed.values.data(), narrow.passed.size());
  EXPECT_GE(narrow.report.event_count, 4);
  EXPECT_EQ(engine.snapshot().timing.gap_count, narrow.report.event_count);
}

// The clean record's OADEV lies within the confidence interval of the screened knocked record's at
// every tau of every channel (each interval at 1 - 0.01 / points: Bonferroni, 99 % family-wise):
// what screening leaves differs from the undisturbed curve by no more than the data it dropped and
// the segments it made allow (at the longest taus only the longer segments contribute, and the
// interval widens accordingly). Unscreened, the knocks and most of all the bias steps they leave
// put the knocked curve outside the clean curve's interval of the same confidence (same data,
// same EDF) at many taus, so the agreement is the screen's doing.
TEST_F(KnockedRecord, AllanCurveAfterScreeningAgreesWithTheCleanRecord) {
  EXPECT_GT(impulse_test::expect_screened_curve_like_clean(*clean_, screen(*knocked_).passed, *knocked_), 20);
}

TEST_F(KnockedRecord, ThresholdOptionDecidesWhatIsAnEvent) {
  ImpulseScreenOptions options;
  options.threshold_sigma = 25.0;
  const auto result = screen(*knocked_, options);
  // The 20-scale spike and the 25-scale step (whose first deviation is 25 noise scales, a little
  // less in scales of the level deviation) are no longer events; the two knocks still are.
  ASSERT_EQ(result.report.event_count, 2);
  EXPECT_NEAR(event_time_s(result.report.events[0].onset_stamp_ns), 600.0, 0.01);
  EXPECT_NEAR(event_time_s(result.report.events[1].onset_stamp_ns), 1500.0, 0.01);
}

TEST_F(KnockedRecord, DisabledScreenPassesEverySampleAtOnce) {
  ImpulseScreenOptions options;
  options.enabled = false;
  allan::ImpulseScreen disabled(options);
  allan::ScreenedSamples passed;
  for (std::size_t k = 0; k < 100; ++k) {
    disabled.push(knocked_->stamps_ns[k], &knocked_->values[k * kChannels], passed);
    EXPECT_EQ(passed.size(), k + 1);
    EXPECT_EQ(disabled.delayed_sample_count(), 0u);
  }
  const auto result = screen(*knocked_, options);
  EXPECT_FALSE(result.report.enabled);
  EXPECT_EQ(result.report.event_count, 0);
  EXPECT_EQ(result.passed.values, knocked_->values);
}

// A knock among the first samples, before any scale exists: the first scale is iterated down
// from the plain RMS (which the knock inflates), and the knock is found like any other.
TEST(ImpulseScreen, KnockDuringTheScaleWarmUpIsFound) {
  Record record = emulate_static_record(120.0, 200.0, 5);
  Knock knock;
  knock.time_s = 2.0;  // the first scale comes from the first 1000 samples: 5 s
  knock.peak_sigma = {0.0, 0.0, 0.0, 100.0, 100.0, 100.0};
  inject(record, knock, sample_noise(record));
  const auto result = screen(record);
  ASSERT_EQ(result.report.event_count, 1);
  EXPECT_NEAR(event_time_s(result.report.events[0].onset_stamp_ns), 2.0, 0.005);
  EXPECT_EQ(channels_of(result.report.events[0]), (std::vector<std::size_t>{3, 4, 5}));
}

// Knocks 1.5 s apart leave 0.25 s between their windows: one event. 4 s apart: two.
TEST(ImpulseScreen, WindowsCloserThanTheMergeGapAreOneEvent) {
  const Record clean = emulate_static_record(120.0, 200.0, 6);
  const auto sigma = sample_noise(clean);
  for (const double separation_s : {1.5, 4.0}) {
    Record record = clean;
    for (const double time_s : {30.0, 30.0 + separation_s}) {
      Knock knock;
      knock.time_s = time_s;
      knock.peak_sigma = {50.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      inject(record, knock, sigma);
    }
    const auto result = screen(record);
    ASSERT_EQ(result.report.event_count, separation_s < 2.0 ? 1 : 2) << separation_s;
    const ImpulseEvent& first = result.report.events.front();
    EXPECT_NEAR(event_time_s(first.onset_stamp_ns), 30.0, 0.005);
    EXPECT_GE(event_time_s(result.report.events.back().end_stamp_ns), 30.0 + separation_s + 1.0);
  }
}

// NaN/Inf values are neither screened nor averaged into a level or a scale: they reach the engine
// (which excludes them). A run of equal stamps never holds more than the delay line's bound.
TEST(ImpulseScreen, NonFiniteValuesAndStuckStampsPassThrough) {
  Record record = emulate_static_record(60.0, 200.0, 7);
  for (std::size_t k = 2000; k < 2100; ++k) record.at(k, 2) = std::numeric_limits<double>::quiet_NaN();
  record.at(5000, 4) = std::numeric_limits<double>::infinity();
  const auto result = screen(record);
  EXPECT_EQ(result.report.event_count, 0);
  EXPECT_EQ(result.passed.size(), record.size());
  for (const double scale : result.report.channel_scales) EXPECT_TRUE(std::isfinite(scale) && scale > 0.0);
  EXPECT_TRUE(std::isinf(result.passed.values[5000 * kChannels + 4]));

  allan::ImpulseScreen stuck{ImpulseScreenOptions()};
  allan::ScreenedSamples passed;
  std::size_t most_delayed = 0;
  for (std::size_t k = 0; k < 200000; ++k) {
    stuck.push(kStartNs, &record.values[(k % record.size()) * kChannels], passed);
    most_delayed = std::max(most_delayed, stuck.delayed_sample_count());
  }
  EXPECT_LE(most_delayed, std::size_t{1} << 16);
  const auto report = stuck.report();
  EXPECT_EQ(report.passed_sample_count + report.dropped_sample_count +
                static_cast<std::int64_t>(stuck.delayed_sample_count()),
            200000);
}

TEST(ImpulseScreen, UnusableOptionsAreRefusedByName) {
  const auto refused_key = [](ImpulseScreenOptions options) -> std::string {
    try {
      allan::ImpulseScreen screen(options);
    } catch (const ConfigError& error) {
      return error.key();
    }
    return "";
  };
  ImpulseScreenOptions options;
  options.threshold_sigma = 2.0;
  EXPECT_EQ(refused_key(options), "threshold_sigma");
  options = ImpulseScreenOptions();
  options.threshold_sigma = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(refused_key(options), "threshold_sigma");
  options = ImpulseScreenOptions();
  options.guard_after_s = -1.0;
  EXPECT_EQ(refused_key(options), "guard_after_s");
  options = ImpulseScreenOptions();
  options.channel_count = 0;
  EXPECT_EQ(refused_key(options), "channel_count");
  options = ImpulseScreenOptions();
  options.gap_factor = 1.0;
  EXPECT_EQ(refused_key(options), "gap_factor");
  EXPECT_EQ(refused_key(ImpulseScreenOptions()), "");
}

}  // namespace
}  // namespace imu_lab
