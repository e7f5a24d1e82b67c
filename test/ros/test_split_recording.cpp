// A recording split into several bags (rosbag record --split) read as one: the same records and the
// same Allan curves, bit for bit, as the unsplit bag, whatever order the files are named in; a lost
// file is a gap the engine splits and pools, and is reported; overlapping or out-of-order files are
// refused naming both; a time window reads exactly the samples inside it.
#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <sensor_msgs/Imu.h>

#include <algorithm>
#include <cmath>

#include "allan_test_support.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/bag/allan_bag_pass.h"
#include "imu_lab/ros_io/bag/allan_report.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "ros_test_support.h"

namespace {

using imu_lab::io::ImuRecord;
using imu_lab::pipeline::AllanSample;
using imu_lab::ros_io::BagRecording;
using imu_lab::test_support::read_allan_summary;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;
using imu_lab::test_support::white_noise_samples;
using imu_lab::test_support::write_imu_bag;

constexpr std::int64_t kIntervalNs = 5'000'000;  // 200 Hz
constexpr std::size_t kCount = 24000;            // 120 s

std::string expect_input_error(const std::function<void()>& action) {
  try {
    action();
  } catch (const imu_lab::InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

std::vector<AllanSample> slice(const std::vector<AllanSample>& samples, std::size_t begin, std::size_t end) {
  return std::vector<AllanSample>(samples.begin() + begin, samples.begin() + end);
}

// One recording of 120 s, whole and cut into three files at uneven places.
class SplitRecording : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = scratch_directory();
    samples_ = white_noise_samples(kCount, kIntervalNs, 18);
    whole_ = directory_ + "/whole.bag";
    write_imu_bag(whole_, samples_);
    const std::size_t cuts[] = {0, 7001, 15999, kCount};
    for (int k = 0; k < 3; ++k) {
      parts_.push_back(directory_ + "/run_" + std::to_string(k) + ".bag");
      write_imu_bag(parts_.back(), slice(samples_, cuts[k], cuts[k + 1]));
    }
  }

  static std::vector<ImuRecord> records(const BagRecording& recording) {
    std::vector<ImuRecord> out;
    imu_lab::ros_io::for_each_imu(recording, "/imu/raw", [&](const ImuRecord& record) { out.push_back(record); });
    return out;
  }

  static std::string directory_, whole_;
  static std::vector<std::string> parts_;
  static std::vector<AllanSample> samples_;
};
std::string SplitRecording::directory_, SplitRecording::whole_;
std::vector<std::string> SplitRecording::parts_;
std::vector<AllanSample> SplitRecording::samples_;

void expect_same_records(const std::vector<ImuRecord>& a, const std::vector<ImuRecord>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].stamp_ns, b[i].stamp_ns) << i;
    ASSERT_EQ(a[i].angular_rate_rad_s, b[i].angular_rate_rad_s) << i;
    ASSERT_EQ(a[i].specific_force_m_s2, b[i].specific_force_m_s2) << i;
  }
}

TEST_F(SplitRecording, FilesInAnyOrderReadAsTheWholeBagWithTheJoinsReported) {
  imu_lab::ros_io::OpenBag split(BagRecording({parts_[2], parts_[0], parts_[1]}));
  EXPECT_EQ(split.ordered_paths(), parts_);
  EXPECT_EQ(split.choose_topic("", "sensor_msgs/Imu").message_count, kCount);
  std::vector<ImuRecord> read;
  split.for_each_imu("/imu/raw", [&](const ImuRecord& record) { read.push_back(record); });
  expect_same_records(read, records(whole_));
  ASSERT_EQ(split.joins().size(), 2u);
  EXPECT_EQ(split.joins()[0].before_path, parts_[0]);
  EXPECT_EQ(split.joins()[1].after_path, parts_[2]);
  EXPECT_NEAR(split.joins()[0].gap_s, kIntervalNs * 1e-9, 1e-12);
}

TEST_F(SplitRecording, AllanCurvesOfTheSplitFilesAreThoseOfTheWholeBagBitForBit) {
  const auto whole = imu_lab::ros_io::run_allan_bag_pass(whole_, {});
  const auto split = imu_lab::ros_io::run_allan_bag_pass(BagRecording({parts_[1], parts_[2], parts_[0]}), {});
  EXPECT_EQ(split.files, parts_);
  EXPECT_EQ(split.snapshot.timing.gap_count, 0);
  for (const auto statistic : imu_lab::allan::kStreamingStatistics) {
    const auto a = imu_lab::ros_io::channel_curves(whole.snapshot, statistic);
    const auto b = imu_lab::ros_io::channel_curves(split.snapshot, statistic);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t c = 0; c < a.size(); ++c) {
      ASSERT_EQ(a[c].points.size(), b[c].points.size());
      ASSERT_GT(a[c].points.size(), 10u);
      for (std::size_t i = 0; i < a[c].points.size(); ++i) {
        EXPECT_EQ(a[c].points[i].deviation, b[c].points[i].deviation);
        EXPECT_EQ(a[c].points[i].deviation_lower, b[c].points[i].deviation_lower);
      }
    }
  }
}

TEST_F(SplitRecording, TheAllanToolTakesTheSplitFilesAndListsThemInItsSummary) {
  const std::string out_whole = directory_ + "/report_whole", out_split = directory_ + "/report_split";
  const auto a = run_tool("allan", whole_ + " --no-plot --no-identify -o " + out_whole);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  const auto b =
      run_tool("allan", parts_[2] + " " + parts_[0] + " " + parts_[1] + " --no-plot --no-identify -o " + out_split);
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_NE(b.output.find("3 split files"), std::string::npos) << b.output;
  EXPECT_EQ(read_file(out_whole + "/oadev.csv"), read_file(out_split + "/oadev.csv"));
  const YAML::Node summary = read_allan_summary(out_split);
  ASSERT_EQ(summary["files"].size(), 3u);
  EXPECT_EQ(summary["files"][0].as<std::string>(), parts_[0]);
  EXPECT_EQ(summary["file_joins"].size(), 2u);
  EXPECT_EQ(summary["time_window"]["description"].as<std::string>(), "whole recording");
}

TEST_F(SplitRecording, ALostFileIsAGapThatIsSplitPooledAndReported) {
  const auto pass = imu_lab::ros_io::run_allan_bag_pass(BagRecording({parts_[0], parts_[2]}), {});
  EXPECT_EQ(pass.snapshot.timing.gap_count, 1);
  ASSERT_EQ(pass.joins.size(), 1u);
  // From the last stamp of the first file to the first of the third: the second's 8998 samples + 1.
  EXPECT_NEAR(pass.joins[0].gap_s, (15999 - 7001 + 1) * kIntervalNs * 1e-9, 1e-9);
  // The engine counts the time missing: the interval less the one sample period it expected.
  EXPECT_NEAR(pass.snapshot.timing.gap_time_s, pass.joins[0].gap_s - kIntervalNs * 1e-9, 1e-6);
}

TEST_F(SplitRecording, OverlappingFilesAreRefusedNamingBoth) {
  const std::string overlapping = directory_ + "/overlapping.bag";
  write_imu_bag(overlapping, slice(samples_, 6000, 9000));
  const std::string message = expect_input_error([&] {
    imu_lab::ros_io::OpenBag bag(BagRecording({parts_[0], overlapping, parts_[1]}));
  });
  EXPECT_NE(message.find(parts_[0]), std::string::npos) << message;
  EXPECT_NE(message.find(overlapping), std::string::npos) << message;
  EXPECT_NE(message.find("overlap"), std::string::npos) << message;
}

TEST_F(SplitRecording, FilesWhoseStampsGoBackAcrossAJoinAreRefusedNamingBoth) {
  // Recorded after the first file, but stamped before its end (another recording's clock).
  const std::string late = directory_ + "/late.bag";
  {
    rosbag::Bag bag(late, rosbag::bagmode::Write);
    for (int i = 0; i < 20; ++i) {
      sensor_msgs::Imu imu;
      imu.header.stamp.fromNSec(static_cast<std::uint64_t>(samples_[100 + i].stamp_ns));
      ros::Time record_time;
      record_time.fromNSec(static_cast<std::uint64_t>(samples_[8000 + i].stamp_ns));
      bag.write("/imu/raw", record_time, imu);
    }
  }
  const std::string message = expect_input_error([&] { records(BagRecording({parts_[0], late})); });
  EXPECT_NE(message.find(parts_[0]), std::string::npos) << message;
  EXPECT_NE(message.find(late), std::string::npos) << message;
  EXPECT_NE(message.find("out of order"), std::string::npos) << message;
}

TEST_F(SplitRecording, AWindowReadsExactlyTheSamplesInsideItAcrossTheFiles) {
  const imu_lab::io::TimeWindow window{30.0, 50.0};
  const auto read = records(BagRecording(parts_, window));
  // Both ends included: stamps 30 s .. 50 s after the first, every 5 ms.
  ASSERT_EQ(read.size(), 4001u);
  EXPECT_EQ(read.front().stamp_ns, samples_[6000].stamp_ns);
  EXPECT_EQ(read.back().stamp_ns, samples_[10000].stamp_ns);
  // The Allan pass over the window equals one over a bag of just those samples.
  const std::string cut = directory_ + "/cut.bag";
  write_imu_bag(cut, slice(samples_, 6000, 10001));
  const auto windowed = imu_lab::ros_io::run_allan_bag_pass(BagRecording(parts_, window), {});
  const auto expected = imu_lab::ros_io::run_allan_bag_pass(cut, {});
  const auto a = imu_lab::ros_io::channel_curves(windowed.snapshot, imu_lab::allan::Statistic::kOverlappingAllan);
  const auto b = imu_lab::ros_io::channel_curves(expected.snapshot, imu_lab::allan::Statistic::kOverlappingAllan);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t c = 0; c < a.size(); ++c) {
    ASSERT_EQ(a[c].points.size(), b[c].points.size());
    for (std::size_t i = 0; i < a[c].points.size(); ++i) EXPECT_EQ(a[c].points[i].deviation, b[c].points[i].deviation);
  }
}

TEST_F(SplitRecording, TheToolsStateTheWindowAndRefuseABadOne) {
  const std::string out = directory_ + "/report_window";
  const auto run = run_tool("allan", whole_ + " --start-s 20 --end-s 80 --no-plot --no-identify -o " + out);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("from 20 s to 80 s after the first stamp"), std::string::npos) << run.output;
  const YAML::Node summary = read_allan_summary(out);
  EXPECT_EQ(summary["time_window"]["start_s"].as<double>(), 20.0);
  EXPECT_EQ(summary["time_window"]["end_s"].as<double>(), 80.0);
  EXPECT_EQ(summary["samples"].as<long long>(), 12001);
  const auto bad = run_tool("allan", whole_ + " --start-s 50 --end-s 40 --no-plot -o " + directory_ + "/bad");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("end must be after its start"), std::string::npos) << bad.output;
  const auto empty = run_tool("allan", whole_ + " --start-s 500 --no-plot -o " + directory_ + "/empty");
  EXPECT_EQ(empty.exit_code, 1) << empty.output;
  EXPECT_NE(empty.output.find("in the window"), std::string::npos) << empty.output;
}

}  // namespace
