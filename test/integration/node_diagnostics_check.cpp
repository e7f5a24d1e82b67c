// rostest checker for a node's diagnostics on bad input (input_health.h), on thermal_compensator:
// a live stream at 100 Hz (IMU) and 10 Hz (temperature), stamped from 1000 s, runs through
// phases: good, NaN samples, a gap, the thermosensor falling silent (stale temperature), a
// temperature outside the model's range. After each bad phase /diagnostics must say what was
// wrong (WARN or ERROR, with the words) and the node must still publish good samples.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using diagnostic_msgs::DiagnosticStatus;

constexpr std::int64_t kImuInterval_ns = 10'000'000;  // 100 Hz
constexpr int kImuPerTemperature = 10;                // thermosensor at 10 Hz
constexpr double kStatusTimeout_s = 10.0;             // generous for a loaded CI machine

class StreamFeeder {
 public:
  explicit StreamFeeder(ros::NodeHandle& node)
      : imu_(node.advertise<sensor_msgs::Imu>("imu/raw", 10000)),
        temperature_(node.advertise<sensor_msgs::Temperature>("imu/temperature", 10000)),
        output_(node.subscribe("imu/thermal", 10000, &StreamFeeder::on_output, this)),
        diagnostics_(node.subscribe("/diagnostics", 100, &StreamFeeder::on_diagnostics, this)) {}

  // Publishes `count` IMU samples at the wall pace of their stamps; a reading every tenth
  // sample unless the thermosensor is silent.
  void feed(int count, double angular_rate_rad_s = 0.01) {
    for (int i = 0; i < count && ros::ok(); ++i) {
      stamp_ns_ += kImuInterval_ns;
      ros::Time stamp;
      stamp.fromNSec(stamp_ns_);
      if (thermosensor_on && (stamp_ns_ / kImuInterval_ns) % kImuPerTemperature == 0) {
        sensor_msgs::Temperature reading;
        reading.header.stamp = stamp;
        reading.temperature = temperature_c;
        temperature_.publish(reading);
      }
      sensor_msgs::Imu sample;
      sample.header.stamp = stamp;
      sample.header.frame_id = "imu_link";
      sample.angular_velocity.x = angular_rate_rad_s;
      sample.linear_acceleration.z = 9.81;
      imu_.publish(sample);
      ros::spinOnce();
      ros::WallDuration(kImuInterval_ns * 1e-9).sleep();
    }
  }
  void skip(double seconds) { stamp_ns_ += static_cast<std::int64_t>(seconds * 1e9); }
  std::int64_t stamp_ns() const { return stamp_ns_; }

  // Feeds good samples until a thermal_compensator status at `level` whose message has `words`
  // has arrived since the previous match; returns that message (empty after the time-out).
  std::string await_status(unsigned char level, const std::string& words) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(kStatusTimeout_s);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      for (const DiagnosticStatus& status : statuses_) {
        if (status.level != level || status.message.find(words) == std::string::npos) continue;
        statuses_.clear();
        return status.message;
      }
      feed(10);
    }
    return "";
  }

  bool await_node(double timeout_s) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      if (imu_.getNumSubscribers() > 0 && temperature_.getNumSubscribers() > 0 && output_.getNumPublishers() > 0) {
        return true;
      }
      ros::WallDuration(0.05).sleep();
    }
    return false;
  }

  // Published samples stamped after `stamp_ns`, and whether all of them are finite.
  std::size_t published_after(std::int64_t stamp_ns, bool* all_finite) const {
    std::size_t count = 0;
    *all_finite = true;
    for (const auto& message : outputs_) {
      if (static_cast<std::int64_t>(message.header.stamp.toNSec()) <= stamp_ns) continue;
      ++count;
      *all_finite =
          *all_finite && std::isfinite(message.angular_velocity.x) && std::isfinite(message.angular_velocity.y);
    }
    return count;
  }

  bool thermosensor_on = true;
  double temperature_c = 25.0;

 private:
  void on_output(const sensor_msgs::Imu::ConstPtr& message) { outputs_.push_back(*message); }
  void on_diagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& array) {
    for (const DiagnosticStatus& status : array->status) {
      if (status.hardware_id == "thermal_compensator") statuses_.push_back(status);
    }
  }

  ros::Publisher imu_, temperature_;
  ros::Subscriber output_, diagnostics_;
  std::int64_t stamp_ns_ = 1000'000'000'000LL;
  std::vector<sensor_msgs::Imu> outputs_;
  std::vector<DiagnosticStatus> statuses_;
};

void expect_good_samples_after(const StreamFeeder& feeder, std::int64_t stamp_ns, const std::string& phase) {
  bool all_finite = false;
  EXPECT_GT(feeder.published_after(stamp_ns, &all_finite), 20u) << "no good samples published after " << phase;
  EXPECT_TRUE(all_finite) << "a NaN/Inf sample was published after " << phase;
}

TEST(NodeDiagnostics, ThermalCompensatorReportsBadInputAndKeepsPublishing) {
  ros::NodeHandle node;
  StreamFeeder feeder(node);
  ASSERT_TRUE(feeder.await_node(30.0)) << "thermal_compensator did not connect";
  feeder.feed(100);  // learns the 100 Hz rate
  EXPECT_NE(feeder.await_status(DiagnosticStatus::OK, "compensating"), "") << "no OK status on good input";

  feeder.feed(5, std::numeric_limits<double>::quiet_NaN());
  const std::int64_t after_nan_ns = feeder.stamp_ns();
  // The five may fall into two reports: the count is not checked, the words are.
  EXPECT_NE(feeder.await_status(DiagnosticStatus::WARN, "samples with NaN/Inf"), "")
      << "no WARN naming the NaN samples";
  expect_good_samples_after(feeder, after_nan_ns, "the NaN samples");

  feeder.skip(0.5);
  feeder.feed(1);
  const std::int64_t after_gap_ns = feeder.stamp_ns();
  EXPECT_NE(feeder.await_status(DiagnosticStatus::WARN, "1 gaps in the stamps"), "") << "no WARN naming the gap";
  expect_good_samples_after(feeder, after_gap_ns, "the gap");

  feeder.thermosensor_on = false;
  feeder.feed(250);
  EXPECT_NE(feeder.await_status(DiagnosticStatus::ERROR, "stale temperature"), "")
      << "no ERROR for the silent thermosensor";
  feeder.thermosensor_on = true;
  const std::int64_t thermosensor_back_ns = feeder.stamp_ns();
  EXPECT_NE(feeder.await_status(DiagnosticStatus::OK, "compensating"), "") << "no OK once the thermosensor is back";
  expect_good_samples_after(feeder, thermosensor_back_ns, "the stale temperature");

  feeder.temperature_c = 90.0;  // the model was fitted from -25 to 69 degC
  EXPECT_NE(feeder.await_status(DiagnosticStatus::WARN, "outside the model's validity range"), "")
      << "no WARN for a temperature outside the model";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_diagnostics_check");
  return RUN_ALL_TESTS();
}
