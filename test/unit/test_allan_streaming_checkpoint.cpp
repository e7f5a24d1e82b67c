// Checkpoint: stop anywhere, save, resume in a fresh engine, feed the rest: bit-identical to the
// uninterrupted run. Files of another version, corrupted or truncated ones are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "allan_streaming_test_support.h"
#include "imu_lab/allan/checkpoint.h"
#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace allan {
namespace {

using namespace testing_support;

std::string temporary_path(const std::string& name) {
  return ::testing::TempDir() + "allan_streaming_" + name + ".ckpt";
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

StreamingOptions options_for_checkpoint() { return test_options(2, 40, 6, 5.0); }

// Rates with a gap and a NaN in the first half, so segments and history are in the state.
struct RecordedRun {
  std::vector<std::vector<double>> rates;
  std::vector<std::int64_t> stamps_ns;
};

RecordedRun make_run(std::size_t count) {
  RecordedRun run;
  run.rates = {synthetic_rate(count, 71, 0.3), synthetic_rate(count, 72)};
  run.rates[1][std::min<std::size_t>(3000, count / 2)] = std::nan("");  // inside short runs too
  std::int64_t stamp = 0;
  for (std::size_t k = 0; k < count; ++k) {
    stamp += (k == 2500) ? 4 * kMillisecondNs : kMillisecondNs;
    run.stamps_ns.push_back(stamp);
  }
  return run;
}

void feed_run(StreamingAllan& engine, const RecordedRun& run, std::size_t begin, std::size_t end) {
  for (std::size_t k = begin; k < end; ++k) engine.push(run.stamps_ns[k], {run.rates[0][k], run.rates[1][k]});
}

void expect_identical(const StreamingSnapshot& resumed, const StreamingSnapshot& uninterrupted) {
  ASSERT_EQ(resumed.curves.size(), uninterrupted.curves.size());
  for (const Statistic statistic : kStreamingStatistics) {
    for (std::size_t c = 0; c < 2; ++c) {
      const auto& a = resumed.curve(statistic, c);
      const auto& b = uninterrupted.curve(statistic, c);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t i = 0; i < a.size(); ++i) {
        const std::string where = statistic_name(statistic) + " m=" + std::to_string(b[i].averaging_factor);
        EXPECT_EQ(a[i].averaging_factor, b[i].averaging_factor) << where;
        EXPECT_EQ(a[i].term_count, b[i].term_count) << where;
        EXPECT_EQ(a[i].alpha, b[i].alpha) << where;
        EXPECT_EQ(a[i].deviation, b[i].deviation) << where;  // bit-identical
        EXPECT_EQ(a[i].edf, b[i].edf) << where;
        EXPECT_EQ(a[i].deviation_lower, b[i].deviation_lower) << where;
        EXPECT_EQ(a[i].deviation_upper, b[i].deviation_upper) << where;
      }
    }
  }
  EXPECT_EQ(resumed.timing.gap_count, uninterrupted.timing.gap_count);
  EXPECT_EQ(resumed.timing.accepted_sample_count, uninterrupted.timing.accepted_sample_count);
  EXPECT_EQ(resumed.timing.interval_rms_deviation_s, uninterrupted.timing.interval_rms_deviation_s);
  EXPECT_EQ(resumed.timing.events.size(), uninterrupted.timing.events.size());
  EXPECT_EQ(resumed.channels[1].non_finite_count, uninterrupted.channels[1].non_finite_count);
  EXPECT_EQ(resumed.channels[1].segment_count, uninterrupted.channels[1].segment_count);
  EXPECT_EQ(resumed.channels[0].offset, uninterrupted.channels[0].offset);
}

class AllanStreamingCheckpointResume : public ::testing::TestWithParam<std::size_t> {};

TEST_P(AllanStreamingCheckpointResume, ResumedRunIsBitIdenticalToTheUninterruptedOne) {
  const std::size_t count = 9000;
  const std::size_t stop = GetParam();
  const RecordedRun run = make_run(count);
  StreamingAllan uninterrupted(options_for_checkpoint());
  feed_run(uninterrupted, run, 0, count);

  const std::string path = temporary_path("resume_" + std::to_string(stop));
  {
    StreamingAllan first_half(options_for_checkpoint());
    feed_run(first_half, run, 0, stop);
    first_half.snapshot();  // a live snapshot must not disturb the state
    first_half.save_checkpoint(path);
  }
  StreamingAllan resumed = StreamingAllan::load_checkpoint(path);
  EXPECT_EQ(resumed.input_sample_count(), static_cast<std::int64_t>(stop));
  EXPECT_EQ(resumed.last_stamp_ns(), run.stamps_ns[stop - 1]);
  feed_run(resumed, run, stop, count);
  expect_identical(resumed.snapshot(), uninterrupted.snapshot());
  std::remove(path.c_str());
}

// During warm-up, just after the gap and the NaN, and late in the run.
INSTANTIATE_TEST_SUITE_P(StopPoints, AllanStreamingCheckpointResume, ::testing::Values(400, 3001, 7777));

class AllanStreamingCheckpointRefusal : public ::testing::Test {
 protected:
  void SetUp() override {
    StreamingAllan engine(options_for_checkpoint());
    feed_run(engine, make_run(3000), 0, 3000);
    engine.save_checkpoint(path_);
    bytes_ = read_bytes(path_);
    ASSERT_GT(bytes_.size(), 64u);
  }
  void TearDown() override { std::remove(path_.c_str()); }

  void expect_refused(const std::string& bytes, const std::string& reason) {
    write_bytes(path_, bytes);
    try {
      StreamingAllan::load_checkpoint(path_);
      FAIL() << "a checkpoint with " << reason << " was accepted";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(path_), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find(reason), std::string::npos) << error.what();
    }
  }

  const std::string path_ = temporary_path("refusal");
  std::string bytes_;
};

TEST_F(AllanStreamingCheckpointRefusal, AnotherVersionIsRefused) {
  std::string bytes = bytes_;
  const std::uint64_t other_version = kStreamingCheckpointVersion + 1;
  bytes.replace(8, sizeof other_version, reinterpret_cast<const char*>(&other_version), sizeof other_version);
  expect_refused(bytes, "version");
}

TEST_F(AllanStreamingCheckpointRefusal, ACorruptedPayloadIsRefused) {
  std::string bytes = bytes_;
  bytes[bytes.size() / 2] ^= 0x10;
  expect_refused(bytes, "checksum");
}

TEST_F(AllanStreamingCheckpointRefusal, ATruncatedFileIsRefused) {
  expect_refused(bytes_.substr(0, bytes_.size() - 100), "truncated");
  expect_refused(bytes_.substr(0, 12), "not a streaming Allan checkpoint");
}

TEST_F(AllanStreamingCheckpointRefusal, AnotherFileIsRefused) {
  expect_refused("IMU,time,gyro_x\n1,2,3\n4,5,6\n7,8,9\n", "not a streaming Allan checkpoint");
  EXPECT_THROW(StreamingAllan::load_checkpoint(path_ + ".missing"), InputError);
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
