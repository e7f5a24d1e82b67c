// The nodes' shared input-health diagnostics (input_health.h), fed stamps directly: each kind of
// bad input gives its WARN/ERROR summary naming what happened, only in the report that covers
// it; a rate change mid-run warns against the learned rate.
#include "imu_lab/ros_io/node/input_health.h"

#include <gtest/gtest.h>
#include <sensor_msgs/Imu.h>

#include <cmath>
#include <limits>

namespace {

using diagnostic_msgs::DiagnosticStatus;
using imu_lab::ros_io::InputHealth;
using imu_lab::ros_io::InputHealthSettings;
using imu_lab::ros_io::StampVerdict;

constexpr std::int64_t kInterval_ns = 10'000'000;  // 100 Hz

struct Stream {
  InputHealth health{"/imu/raw", InputHealthSettings{}};
  std::int64_t stamp_ns = 1'000'000'000'000LL;

  void feed(int count, std::int64_t interval_ns = kInterval_ns) {
    for (int i = 0; i < count; ++i) {
      stamp_ns += interval_ns;
      health.check_stamp(stamp_ns);
    }
  }
  diagnostic_updater::DiagnosticStatusWrapper report() {
    diagnostic_updater::DiagnosticStatusWrapper status;
    health.fill(status, "fine");
    return status;
  }
};

std::string value_of(const diagnostic_updater::DiagnosticStatusWrapper& status, const std::string& key) {
  for (const auto& pair : status.values) {
    if (pair.key == key) return pair.value;
  }
  return "(missing)";
}

TEST(InputHealth, GoodInputIsOkWithTheLearnedRate) {
  Stream stream;
  stream.feed(100);
  const auto status = stream.report();
  EXPECT_EQ(status.level, DiagnosticStatus::OK) << status.message;
  EXPECT_EQ(status.message, "fine");
  EXPECT_EQ(value_of(status, "expected rate [Hz]"), "100 (learned)");
  EXPECT_NEAR(std::stod(value_of(status, "input rate from stamps [Hz]")), 100.0, 1e-6);
}

TEST(InputHealth, NoInputWarnsNamingTheTopic) {
  Stream stream;
  const auto status = stream.report();
  EXPECT_EQ(status.level, DiagnosticStatus::WARN);
  EXPECT_EQ(status.message, "no input on /imu/raw since the last report");
}

TEST(InputHealth, NonFiniteSamplesWarnOnceThenTheNextReportIsOk) {
  Stream stream;
  stream.feed(100);
  stream.health.count_non_finite();
  stream.health.count_non_finite();
  const auto warned = stream.report();
  EXPECT_EQ(warned.level, DiagnosticStatus::WARN);
  EXPECT_EQ(warned.message, "2 samples with NaN/Inf");
  stream.feed(100);
  const auto recovered = stream.report();
  EXPECT_EQ(recovered.level, DiagnosticStatus::OK) << recovered.message;
  EXPECT_EQ(value_of(recovered, "NaN/Inf samples"), "2");
}

// A sensor_msgs/Imu whose triad is marked as not provided (covariance[0] = -1) is unusable to
// every node of the chain, and said so apart from NaN (the message conversion makes its values NaN).
TEST(InputHealth, ASampleWithoutATriadIsCountedApartFromNaN) {
  Stream stream;
  stream.feed(100);
  sensor_msgs::Imu message;
  message.header.stamp.fromNSec(static_cast<std::uint64_t>(stream.stamp_ns));
  message.linear_acceleration.z = 9.8;
  EXPECT_TRUE(stream.health.check_values(imu_lab::ros_io::to_imu_record(message)));
  message.angular_velocity_covariance[0] = -1.0;
  const auto record = imu_lab::ros_io::to_imu_record(message);
  EXPECT_FALSE(record.has_angular_rate);
  EXPECT_TRUE(std::isnan(record.angular_rate_rad_s.x())) << "the zeros of a triad not provided are not data";
  EXPECT_FALSE(stream.health.check_values(record));
  message.angular_velocity_covariance[0] = 0.0;
  message.linear_acceleration.x = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(stream.health.check_values(imu_lab::ros_io::to_imu_record(message)));
  const auto status = stream.report();
  EXPECT_EQ(status.level, DiagnosticStatus::WARN);
  EXPECT_EQ(status.message,
            "1 samples with NaN/Inf; 1 samples without angular rate or specific force (covariance[0] = -1)");
}

// Finite but absurd values (1e308 rad/s) overflow whatever a node computes from them: the nodes
// drop them like NaN (they passed calibration_corrector, thermal_compensator and the navigator),
// counted apart so the report says what was wrong.
TEST(InputHealth, AValueBeyond1e100IsUnusableAndCountedApartFromNaN) {
  Stream stream;
  stream.feed(100);
  sensor_msgs::Imu message;
  message.header.stamp.fromNSec(static_cast<std::uint64_t>(stream.stamp_ns));
  message.linear_acceleration.z = 9.8;
  message.angular_velocity.y = 1e100;  // the largest usable value
  EXPECT_TRUE(stream.health.check_values(imu_lab::ros_io::to_imu_record(message)));
  message.angular_velocity.y = 1e308;
  EXPECT_FALSE(stream.health.check_values(imu_lab::ros_io::to_imu_record(message)));
  EXPECT_FALSE(stream.health.check_triads(Eigen::Vector3d(0.0, 0.0, -1e101), Eigen::Vector3d::Zero()));
  EXPECT_FALSE(stream.health.check_triads(Eigen::Vector3d::Zero(), Eigen::Vector3d(std::nan(""), 0.0, 0.0)));
  const auto status = stream.report();
  EXPECT_EQ(status.level, DiagnosticStatus::WARN);
  EXPECT_EQ(status.message, "1 samples with NaN/Inf; 2 samples with a value beyond +-1e100");
  EXPECT_EQ(value_of(status, "samples with a value beyond +-1e100"), "2");
}

TEST(InputHealth, AGapIsCountedWithTheMissingTimeAndDoesNotLookLikeASlowRate) {
  Stream stream;
  stream.feed(100);
  stream.stamp_ns += 500'000'000 + kInterval_ns;  // half a second missing
  EXPECT_EQ(stream.health.check_stamp(stream.stamp_ns), StampVerdict::kAfterGap);
  stream.feed(50);
  const auto status = stream.report();
  EXPECT_EQ(status.level, DiagnosticStatus::WARN);
  EXPECT_EQ(status.message, "1 gaps in the stamps (0.500 s missing)");
  EXPECT_NEAR(std::stod(value_of(status, "longest gap [s]")), 0.51, 1e-9);
}

TEST(InputHealth, DuplicateAndOutOfOrderStampsAreNamedApart) {
  Stream stream;
  stream.feed(100);
  EXPECT_EQ(stream.health.check_stamp(stream.stamp_ns), StampVerdict::kDuplicate);
  EXPECT_EQ(stream.health.check_stamp(stream.stamp_ns - 3 * kInterval_ns), StampVerdict::kOutOfOrder);
  stream.feed(10);  // the previous stamp did not move back: no gap after the out-of-order one
  const auto status = stream.report();
  EXPECT_EQ(status.message, "1 duplicate stamps; 1 out-of-order stamps");
  EXPECT_EQ(value_of(status, "gaps"), "0");
}

TEST(InputHealth, ARateChangeMidRunWarnsAgainstTheLearnedRate) {
  Stream stream;
  stream.feed(100);
  EXPECT_EQ(stream.report().level, DiagnosticStatus::OK);
  stream.feed(100, 2 * kInterval_ns);  // 50 Hz: slower, but no interval is a gap (gap factor 3)
  const auto status = stream.report();
  EXPECT_EQ(status.level, DiagnosticStatus::WARN);
  EXPECT_EQ(status.message, "input rate 50 Hz, expected 100 Hz");
}

TEST(InputHealth, TheExpectedRateCanBeGiven) {
  InputHealthSettings settings;
  settings.expected_rate_hz = 200.0;
  Stream stream{InputHealth("/imu/raw", settings)};
  stream.feed(100);
  EXPECT_EQ(stream.report().message, "input rate 100 Hz, expected 200 Hz");
}

TEST(InputHealth, ANodesOwnConditionTakesItsLevelAndTheWorstLevelWins) {
  Stream stream;
  const auto stale = stream.health.define_condition("stale temperature", DiagnosticStatus::ERROR);
  stream.feed(100);
  stream.health.count_non_finite();
  stream.health.count(stale);
  const auto status = stream.report();
  EXPECT_EQ(status.level, DiagnosticStatus::ERROR);
  EXPECT_EQ(status.message, "1 samples with NaN/Inf; 1 stale temperature");
  EXPECT_EQ(value_of(status, "stale temperature"), "1");
}

TEST(InputHealth, AHeldConditionKeepsItsLevelForItsReportsThenTheSummaryIsOk) {
  Stream stream;
  const auto knocks = stream.health.define_condition("knocks", DiagnosticStatus::WARN, /*hold_reports=*/3);
  stream.feed(100);
  stream.health.count(knocks);
  auto status = stream.report();
  EXPECT_EQ(status.level, DiagnosticStatus::WARN);
  EXPECT_EQ(status.message, "1 knocks");
  for (int later = 1; later <= 3; ++later) {
    stream.feed(100);
    status = stream.report();
    EXPECT_EQ(status.level, DiagnosticStatus::WARN) << "report " << later << " after the knock";
    EXPECT_EQ(status.message, "knocks: 1 in all, the last one " + std::to_string(later) + " reports ago");
  }
  stream.feed(100);
  status = stream.report();
  EXPECT_EQ(status.level, DiagnosticStatus::OK);
  EXPECT_EQ(status.message, "fine");
  EXPECT_EQ(value_of(status, "knocks"), "1");
}

}  // namespace
