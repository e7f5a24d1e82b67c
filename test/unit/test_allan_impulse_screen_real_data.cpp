// The impulse screen and the output-step detector on real static recordings of three ADIS16405
// units (the reference data's real_static, under IMU_LAB_REFERENCE_DIR; imported as the CSV importer does: deg/s and g
// to SI): the knocked unit's two large knocks are found where they happened, the other two units raise no event with
// the default threshold, and the output steps are the parts' LSBs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <istream>
#include <streambuf>
#include <string>

#include "imu_lab/allan/impulse_screen.h"
#include "imu_lab/allan/output_step.h"
#include "imu_lab/io/csv_imu_import.h"

#ifndef IMU_LAB_REFERENCE_DIR
#define IMU_LAB_REFERENCE_DIR "../shared/reference"
#endif

namespace imu_lab {
namespace {

// Reads a child process's output as an istream (xzcat's, so the test needs no decompressed copy).
class PipeBuffer : public std::streambuf {
 public:
  explicit PipeBuffer(FILE* pipe) : pipe_(pipe) {}

 protected:
  int_type underflow() override {
    const std::size_t count = std::fread(buffer_, 1, sizeof buffer_, pipe_);
    if (count == 0) return traits_type::eof();
    setg(buffer_, buffer_, buffer_ + count);
    return traits_type::to_int_type(buffer_[0]);
  }

 private:
  FILE* pipe_;
  char buffer_[1 << 16];
};

struct UnitResult {
  allan::ImpulseScreenReport screen;
  allan::ImpulseScreenReport narrow;  // no guards, no merging: each flagged stretch on its own
  std::vector<allan::ChannelOutputStep> steps;
  std::size_t samples = 0;
};

// The unit's record through the CSV importer (as `import_csv --gyro-unit deg_s --accel-unit g`),
// the screen with default options and the step detector.
UnitResult screen_unit(int unit) {
  const std::string path =
      std::string(IMU_LAB_REFERENCE_DIR) + "/real_static/adis16405_unit" + std::to_string(unit) + ".csv.xz";
  UnitResult result;
  FILE* pipe = ::popen(("xzcat '" + path + "'").c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "cannot run xzcat on " << path;
    return result;
  }
  PipeBuffer buffer(pipe);
  std::istream in(&buffer);
  io::CsvImportOptions options;
  options.gyro_unit = io::AngularRateUnit::kDegreePerSecond;
  options.accel_unit = io::SpecificForceUnit::kStandardGravity;
  options.time_offset_ns = 1000000000;
  allan::ImpulseScreen screen{allan::ImpulseScreenOptions()};
  allan::ImpulseScreenOptions narrow_options;
  narrow_options.guard_before_s = narrow_options.guard_after_s = narrow_options.merge_gap_s = 0.0;
  allan::ImpulseScreen narrow(narrow_options);
  allan::OutputStepDetector steps(6);
  allan::ScreenedSamples passed;
  const auto summary = io::parse_imu_csv(in, options, path, [&](const io::ImuCsvSample& sample) {
    const double values[6] = {sample.angular_rate_rad_s[0],  sample.angular_rate_rad_s[1],
                              sample.angular_rate_rad_s[2],  sample.specific_force_m_s2[0],
                              sample.specific_force_m_s2[1], sample.specific_force_m_s2[2]};
    steps.push(values);
    screen.push(sample.stamp_ns, values, passed);
    narrow.push(sample.stamp_ns, values, passed);
    passed.clear();
  });
  EXPECT_EQ(::pclose(pipe), 0) << "xzcat " << path;
  screen.finish(passed);
  narrow.finish(passed);
  result.screen = screen.report();
  result.narrow = narrow.report();
  result.steps = steps.channels();
  result.samples = summary.accepted_rows;
  return result;
}

double relative_s(const allan::ImpulseScreenReport& report, std::int64_t stamp_ns) {
  return (stamp_ns - report.first_stamp_ns) * 1e-9;
}

std::string describe(const allan::ImpulseScreenReport& report) {
  std::string text;
  char line[160];
  for (const auto& event : report.events) {
    std::snprintf(line, sizeof line, "  onset %.2f s, window %.2f-%.2f s, peak %.1f scales in channel %zu\n",
                  relative_s(report, event.onset_stamp_ns), relative_s(report, event.start_stamp_ns),
                  relative_s(report, event.end_stamp_ns), event.peak_sigma, event.peak_channel);
    text += line;
  }
  return text;
}

// Every event names the channels that crossed the threshold, each with a peak beyond it.
void expect_channels_over_threshold(const allan::ImpulseScreenReport& report) {
  for (const auto& event : report.events) {
    const double onset_s = relative_s(report, event.onset_stamp_ns);
    EXPECT_GE(event.flagged_sample_count, 1) << onset_s;
    EXPECT_FALSE(event.channels.empty()) << "event at " << onset_s << " s names no channel";
    for (const auto& peak : event.channels) EXPECT_GT(std::abs(peak.peak_sigma), report.threshold_sigma) << onset_s;
    EXPECT_GE(std::abs(event.peak_sigma), report.threshold_sigma) << onset_s;
  }
}

void expect_adis_steps(const UnitResult& result, int unit) {
  ASSERT_EQ(result.steps.size(), 6u);
  for (int c = 0; c < 6; ++c) {
    const double expected = c < 3 ? 0.05 * M_PI / 180.0 : 0.00333 * 9.80665;
    EXPECT_TRUE(result.steps[c].quantised) << "unit " << unit << " channel " << c;
    EXPECT_NEAR(result.steps[c].step / expected, 1.0, 1e-12) << "unit " << unit << " channel " << c;
  }
}

// Unit 4 was knocked near 4045 s and 5146 s from the start (up to 17 deg/s and 1.5 g): each is
// one event whose first sample over the threshold lies within 1 s of it, involving the
// accelerometers at tens of scales. Its smaller disturbances (near 117-119 s and 3336 s) may be
// events too; nothing else is.
TEST(ImpulseScreenRealData, KnockedUnitFourHasItsKnocksReported) {
  const UnitResult result = screen_unit(4);
  ASSERT_EQ(result.samples, 1000000u);
  const auto& report = result.screen;
  EXPECT_GE(report.event_count, 2);
  EXPECT_LE(report.event_count, 4) << describe(report);
  for (const double knock_s : {4045.0, 5146.0}) {
    int found = 0;
    for (const auto& event : report.events) {
      if (std::abs(relative_s(report, event.onset_stamp_ns) - knock_s) > 1.0) continue;
      ++found;
      EXPECT_GT(std::abs(event.peak_sigma), 50.0) << knock_s;
      EXPECT_GE(event.peak_channel, 3u) << knock_s;  // the accelerometers saw it most
      EXPECT_LE(relative_s(report, event.start_stamp_ns), knock_s + 0.5);
    }
    EXPECT_EQ(found, 1) << "knock near " << knock_s << " s\n" << describe(report);
  }
  expect_channels_over_threshold(report);
  // Unmerged, the same samples are flagged, in more and shorter events (the first disturbance
  // alone is three: 117.10, 117.69 and 118.99 s).
  EXPECT_GT(result.narrow.event_count, report.event_count);
  expect_channels_over_threshold(result.narrow);
  expect_adis_steps(result, 4);
}

// Units 5 and 6 were not knocked: their isolated one-sample accelerometer excursions (up to about
// 10.5 scales) stay below the default threshold.
TEST(ImpulseScreenRealData, UnitsFiveAndSixRaiseNoEvent) {
  for (const int unit : {5, 6}) {
    const UnitResult result = screen_unit(unit);
    ASSERT_EQ(result.samples, 1000000u);
    EXPECT_EQ(result.screen.event_count, 0) << "unit " << unit << "\n" << describe(result.screen);
    EXPECT_EQ(result.screen.dropped_sample_count, 0);
    expect_adis_steps(result, unit);
  }
}

}  // namespace
}  // namespace imu_lab
