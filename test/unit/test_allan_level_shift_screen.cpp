// The level-shift screen on emulated records: silent on clean data for hours, a tilt (a step in
// the level and its return, no impulse) found as two shifts with their stamps, channels and sizes,
// each one a segment boundary of the accelerometer's channels in the engine (the gyros untouched),
// and the Allan curve of the tilted record after screening that of the clean record within its
// confidence.
#include "imu_lab/allan/level_shift_screen.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "imu_lab/common/config_error.h"
#include "impulse_test_records.h"

namespace imu_lab {
namespace {

using allan::LevelShiftReport;
using allan::LevelShiftScreenOptions;
using impulse_test::emulate_static_record;
using impulse_test::kChannels;
using impulse_test::kStartNs;
using impulse_test::Record;

struct ShiftRun {
  LevelShiftReport report;
  allan::ScreenedSamples passed;
};

ShiftRun screen_shifts(const Record& record, LevelShiftScreenOptions options = LevelShiftScreenOptions()) {
  options.channel_count = kChannels;
  allan::LevelShiftScreen screen(options);
  ShiftRun run;
  for (std::size_t k = 0; k < record.size(); ++k)
    screen.push(record.stamps_ns[k], &record.values[k * kChannels], run.passed);
  screen.finish(run.passed);
  run.report = screen.report();
  return run;
}

double time_s(std::int64_t stamp_ns) { return (stamp_ns - kStartNs) * 1e-9; }

// Per channel the standard deviation of D = mean(next W) - mean(previous W) over the record: what
// the screen's scale estimates (consistently for Gaussian noise).
std::array<double, kChannels> difference_sigma(const Record& record, double window_s) {
  const auto w = static_cast<std::size_t>(std::llround(window_s * record.rate_hz));
  std::array<double, kChannels> sigma{};
  for (std::size_t c = 0; c < kChannels; ++c) {
    std::vector<double> prefix(record.size() + 1, 0.0);
    for (std::size_t k = 0; k < record.size(); ++k) prefix[k + 1] = prefix[k] + record.at(k, c);
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t k = w; k + w <= record.size(); ++k) {
      const double d = (prefix[k + w] - prefix[k]) / w - (prefix[k] - prefix[k - w]) / w;
      sum += d * d;
      ++count;
    }
    sigma[c] = std::sqrt(sum / count);
  }
  return sigma;
}

// Three hours of clean data over two seeds and two rates: no shift. D is Gaussian for this noise,
// and 10 scales has a probability of 1.5e-23 per independent window. The scale itself is that of D:
// within 15 % of its plain standard deviation over the record (the estimate forgets over an hour,
// some 360 independent 10 s windows: a relative error of about 4 %).
TEST(LevelShiftScreen, CleanRecordsRaiseNoShiftForHours) {
  impulse_test::for_each_clean_record([](const Record& record, const std::string& where) {
    const ShiftRun result = screen_shifts(record);
    EXPECT_EQ(result.report.event_count, 0) << where;
    EXPECT_EQ(result.report.masked_sample_count, 0);
    EXPECT_EQ(result.passed.stamps_ns, record.stamps_ns);
    EXPECT_EQ(result.passed.values, record.values);
    const auto expected = difference_sigma(record, LevelShiftScreenOptions().window_s);
    for (std::size_t c = 0; c < kChannels; ++c) {
      EXPECT_NEAR(result.report.channel_scales[c] / expected[c], 1.0, 0.15)
          << "channel " << c << ", " << where << ": scale " << result.report.channel_scales[c] << ", sigma of D "
          << expected[c];
    }
  });
}

// Half an hour at 100 Hz; from 900 s to 1260 s accelerometer x reads 0.03 m/s^2 more and y 0.02
// less (a tilt of about 3 mrad, as unit 4's; doc/impulse_screen.md), with no impulse.
class TiltedRecord : public ::testing::Test {
 protected:
  static constexpr double kTiltStartS = 900.0, kTiltEndS = 1260.0;
  static constexpr double kShiftX = 0.03, kShiftY = -0.02;
  static void SetUpTestSuite() {
    clean_ = new Record(emulate_static_record(1800.0, 100.0, 3));
    tilted_ = new Record(*clean_);
    for (std::size_t k = 0; k < tilted_->size(); ++k) {
      const double t = tilted_->time_s(k);
      if (t < kTiltStartS || t >= kTiltEndS) continue;
      tilted_->at(k, 3) += kShiftX;
      tilted_->at(k, 4) += kShiftY;
    }
  }
  static void TearDownTestSuite() {
    delete clean_;
    delete tilted_;
  }
  static Record* clean_;
  static Record* tilted_;
};
Record* TiltedRecord::clean_ = nullptr;
Record* TiltedRecord::tilted_ = nullptr;

TEST_F(TiltedRecord, EachStepIsOneShiftWithItsStampAndSizes) {
  const ShiftRun result = screen_shifts(*tilted_);
  ASSERT_EQ(result.report.event_count, 2);
  ASSERT_EQ(result.report.events.size(), 2u);
  const double step_times_s[2] = {kTiltStartS, kTiltEndS};
  const double signs[2] = {1.0, -1.0};
  for (int e = 0; e < 2; ++e) {
    const auto& shift = result.report.events[e];
    EXPECT_NEAR(time_s(shift.step_stamp_ns), step_times_s[e], 0.5) << "shift " << e;
    EXPECT_LT(time_s(shift.start_stamp_ns), step_times_s[e]);
    EXPECT_GT(time_s(shift.end_stamp_ns), step_times_s[e]);
    ASSERT_EQ(shift.channels.size(), 2u) << "shift " << e << ": only the accelerometer's x and y moved";
    EXPECT_EQ(shift.channels[0].channel, 3u);
    EXPECT_EQ(shift.channels[1].channel, 4u);
    EXPECT_EQ(shift.masked_channels, (std::vector<std::size_t>{3, 4, 5})) << "shift " << e << ": the triad";
    // D at its peak is the step plus noise of one scale: within 4 scales.
    EXPECT_NEAR(shift.channels[0].shift, signs[e] * kShiftX, 4.0 * result.report.channel_scales[3]);
    EXPECT_NEAR(shift.channels[1].shift, signs[e] * kShiftY, 4.0 * result.report.channel_scales[4]);
  }
  // Every sample passed, in order; around each step the accelerometer's values are NaN and only
  // there, the gyros' never.
  ASSERT_EQ(result.passed.stamps_ns, tilted_->stamps_ns);
  std::int64_t masked = 0;
  for (std::size_t k = 0; k < tilted_->size(); ++k) {
    const std::int64_t stamp_ns = tilted_->stamps_ns[k];
    const bool inside = std::any_of(result.report.events.begin(), result.report.events.end(), [&](const auto& shift) {
      return stamp_ns >= shift.start_stamp_ns && stamp_ns <= shift.end_stamp_ns;
    });
    masked += inside;
    for (std::size_t c = 0; c < kChannels; ++c) {
      const double value = result.passed.values[k * kChannels + c];
      if (inside && c >= 3) {
        EXPECT_TRUE(std::isnan(value)) << "sample " << k << " channel " << c;
      } else {
        EXPECT_EQ(value, tilted_->at(k, c)) << "sample " << k << " channel " << c;
      }
    }
  }
  EXPECT_EQ(result.report.masked_sample_count, masked);
  EXPECT_EQ(result.report.channel_masked_counts[0], 0);
  EXPECT_EQ(result.report.channel_masked_counts[3], masked);
}

// The NaNs around each step split the accelerometer's runs in the engine: one more segment per
// shift on its channels, none on the gyros', and no gap.
TEST_F(TiltedRecord, TheEngineStartsASegmentOfTheTriadAtEveryShift) {
  const ShiftRun result = screen_shifts(*tilted_);
  const auto snapshot = impulse_test::engine_snapshot(result.passed.stamps_ns, result.passed.values);
  EXPECT_EQ(snapshot.timing.gap_count, 0);
  for (std::size_t c = 0; c < kChannels; ++c) {
    EXPECT_EQ(snapshot.channels[c].segment_count, c >= 3 ? result.report.event_count + 1 : 1) << "channel " << c;
  }
}

// The clean record's OADEV lies within the confidence interval of the screened tilted record's at
// every tau of every channel (each interval at 1 - 0.01 / points: Bonferroni, 99 % family-wise).
// Unscreened, the tilt puts the accelerometer's x and y curves outside the clean curve's interval
// of the same confidence at many taus, so the agreement is the screen's doing.
TEST_F(TiltedRecord, AllanCurveAfterScreeningAgreesWithTheCleanRecord) {
  EXPECT_GT(impulse_test::expect_screened_curve_like_clean(*clean_, screen_shifts(*tilted_).passed, *tilted_), 10);
}

// A step across a stamp gap (a knock the impulse screen dropped, a recording paused) is already a
// segment boundary: no window spans the gap, so it is not a shift.
TEST_F(TiltedRecord, AStepAcrossAGapIsNotAShift) {
  Record gapped;
  gapped.rate_hz = tilted_->rate_hz;
  for (std::size_t k = 0; k < tilted_->size(); ++k) {
    const double t = tilted_->time_s(k);
    if ((t > kTiltStartS - 2.0 && t < kTiltStartS + 2.0) || (t > kTiltEndS - 2.0 && t < kTiltEndS + 2.0)) continue;
    gapped.stamps_ns.push_back(tilted_->stamps_ns[k]);
    gapped.values.insert(gapped.values.end(), tilted_->values.begin() + k * kChannels,
                         tilted_->values.begin() + (k + 1) * kChannels);
  }
  const ShiftRun result = screen_shifts(gapped);
  EXPECT_EQ(result.report.event_count, 0);
  EXPECT_EQ(result.passed.stamps_ns, gapped.stamps_ns);
  EXPECT_EQ(result.passed.values, gapped.values);
}

TEST_F(TiltedRecord, DisabledScreenPassesEverySampleAtOnce) {
  LevelShiftScreenOptions options;
  options.enabled = false;
  options.channel_count = kChannels;
  allan::LevelShiftScreen screen(options);
  allan::ScreenedSamples passed;
  screen.push(tilted_->stamps_ns[0], &tilted_->values[0], passed);
  EXPECT_EQ(passed.size(), 1u);
  const ShiftRun result = screen_shifts(*tilted_, options);
  EXPECT_EQ(result.report.event_count, 0);
  EXPECT_EQ(result.passed.stamps_ns, tilted_->stamps_ns);
  EXPECT_EQ(result.passed.values, tilted_->values);
}

TEST(LevelShiftScreen, UnusableOptionsAreRefusedByName) {
  const auto refused_key = [](LevelShiftScreenOptions options) -> std::string {
    try {
      allan::LevelShiftScreen screen(options);
    } catch (const ConfigError& error) {
      return error.what();
    }
    return "";
  };
  LevelShiftScreenOptions options;
  options.window_s = 0.0;
  EXPECT_NE(refused_key(options).find("window_s"), std::string::npos);
  options = LevelShiftScreenOptions();
  options.threshold_sigma = 2.0;
  EXPECT_NE(refused_key(options).find("threshold_sigma"), std::string::npos);
  options = LevelShiftScreenOptions();
  options.scale_warm_up_s = 5.0;
  EXPECT_NE(refused_key(options).find("scale_warm_up_s"), std::string::npos);
  options = LevelShiftScreenOptions();
  options.gap_factor = 1.0;
  EXPECT_NE(refused_key(options).find("gap_factor"), std::string::npos);
}

}  // namespace
}  // namespace imu_lab
