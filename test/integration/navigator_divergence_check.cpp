// rostest checker for strapdown_navigator's own state check (navigation_session.h): a live stream
// of a level IMU at rest (100 Hz, stamped from 1000 s) gets one finite but absurd sample
// (1e50 rad/s and m/s^2: within +-1e100, so not dropped as unusable input like 1e308 is, but
// the state leaves every bound). The node must then stop publishing odometry, say on /diagnostics at
// ERROR level where (the sample's stamp) and that it stopped, keep saying it while good samples
// arrive, and start again only when ~reinitialise is called. Waits on events, with time-outs.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <std_srvs/Trigger.h>

#include <functional>
#include <string>

#include "imu_lab/common/stamps.h"
#include "imu_lab/pipeline/navigation_csv.h"

namespace {

using diagnostic_msgs::DiagnosticStatus;

constexpr std::int64_t kInterval_ns = 10'000'000;  // 100 Hz
constexpr double kTimeout_s = 30.0;                // generous for a loaded CI machine

class Feeder {
 public:
  explicit Feeder(ros::NodeHandle& node)
      : imu_(node.advertise<sensor_msgs::Imu>("imu/corrected", 10000)),
        odometry_(node.subscribe("nav/odometry", 10000, &Feeder::on_odometry, this)),
        diagnostics_(node.subscribe("/diagnostics", 100, &Feeder::on_diagnostics, this)) {}

  // Publishes `count` samples 10 ms apart in stamp (at rest: gravity up, no rate) or one absurd.
  void feed(int count, double value = 0.0) {
    for (int i = 0; i < count && ros::ok(); ++i) {
      stamp_ns_ += kInterval_ns;
      sensor_msgs::Imu sample;
      sample.header.stamp.fromNSec(stamp_ns_);
      sample.header.frame_id = "imu_link";
      sample.angular_velocity.x = sample.angular_velocity.y = sample.angular_velocity.z = value;
      sample.linear_acceleration.x = sample.linear_acceleration.y = value;
      sample.linear_acceleration.z = value != 0.0 ? value : 9.81;
      imu_.publish(sample);
      ros::spinOnce();
      ros::WallDuration(0.002).sleep();
    }
  }

  // Feeds good samples until `done` holds (or the time-out); returns whether it did.
  bool feed_until(const std::function<bool()>& done) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(kTimeout_s);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      ros::spinOnce();
      if (done()) return true;
      feed(10);
    }
    return false;
  }

  bool await_node() {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(kTimeout_s);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      if (imu_.getNumSubscribers() > 0 && odometry_.getNumPublishers() > 0) return true;
      ros::WallDuration(0.05).sleep();
    }
    return false;
  }

  std::int64_t stamp_ns() const { return stamp_ns_; }
  std::size_t odometry_count() const { return odometry_count_; }
  std::int64_t last_odometry_ns() const { return last_odometry_ns_; }
  const DiagnosticStatus& last_status() const { return last_status_; }
  std::size_t statuses() const { return statuses_; }

  static std::string value_of(const DiagnosticStatus& status, const std::string& key) {
    for (const auto& pair : status.values) {
      if (pair.key == key) return pair.value;
    }
    return "";
  }

 private:
  void on_odometry(const nav_msgs::Odometry::ConstPtr& message) {
    ++odometry_count_;
    last_odometry_ns_ = static_cast<std::int64_t>(message->header.stamp.toNSec());
  }
  void on_diagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& array) {
    for (const DiagnosticStatus& status : array->status) {
      if (status.hardware_id != "strapdown_navigator") continue;
      last_status_ = status;
      ++statuses_;
    }
  }

  ros::Publisher imu_;
  ros::Subscriber odometry_, diagnostics_;
  std::int64_t stamp_ns_ = 1000'000'000'000LL;
  std::size_t odometry_count_ = 0, statuses_ = 0;
  std::int64_t last_odometry_ns_ = 0;
  DiagnosticStatus last_status_;
};

TEST(NavigatorDivergence, StopsReportsAndStartsAgainOnlyWhenTold) {
  ros::NodeHandle node;
  Feeder feeder(node);
  ASSERT_TRUE(feeder.await_node()) << "strapdown_navigator did not connect";
  feeder.feed(100);
  ASSERT_TRUE(feeder.feed_until([&] { return feeder.odometry_count() >= 100; })) << "no odometry on good input";

  feeder.feed(1, 1e50);
  const std::int64_t absurd_ns = feeder.stamp_ns();
  const std::string where = imu_lab::format_stamp_s(absurd_ns);
  ASSERT_TRUE(feeder.feed_until([&] {
    const DiagnosticStatus& s = feeder.last_status();
    return s.level == DiagnosticStatus::ERROR && s.message.find("navigation stopped") != std::string::npos &&
           std::stoul("0" + Feeder::value_of(s, "samples ignored since")) >= 200;
  })) << "no ERROR status naming the stop; last: "
      << feeder.last_status().message;
  const DiagnosticStatus stopped = feeder.last_status();
  EXPECT_NE(stopped.message.find(where), std::string::npos) << stopped.message;
  EXPECT_NE(stopped.message.find("reinitialise"), std::string::npos) << stopped.message;
  EXPECT_EQ(Feeder::value_of(stopped, "navigation stopped at stamp [s]"), where);
  // Nothing after the absurd sample: the last odometry is the one before it.
  EXPECT_EQ(feeder.last_odometry_ns(), absurd_ns - kInterval_ns);

  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call("strapdown_navigator/reinitialise", trigger));
  EXPECT_TRUE(trigger.response.success) << trigger.response.message;
  const std::size_t before = feeder.odometry_count();
  ASSERT_TRUE(feeder.feed_until([&] { return feeder.odometry_count() >= before + 50; }))
      << "no odometry after ~reinitialise";
  EXPECT_GT(feeder.last_odometry_ns(), absurd_ns);
  ASSERT_TRUE(feeder.feed_until([&] {
    const DiagnosticStatus& s = feeder.last_status();
    return Feeder::value_of(s, "re-initialisations") == "1" && s.level != DiagnosticStatus::ERROR;
  })) << "the ERROR stays after ~reinitialise: "
      << feeder.last_status().message;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "navigator_divergence_check");
  return RUN_ALL_TESTS();
}
