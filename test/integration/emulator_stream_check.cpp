// rostest checker for imu_emulator: collects a fixed number of messages from each topic and
// checks what the node promises, from the stamps (never from arrival times or wall-clock rates,
// which a loaded CI machine distorts).
#include <gtest/gtest.h>
#include <imu_lab/ImuIncrement.h>
#include <imu_lab/ImuTruth.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace {

struct Collected {
  std::vector<sensor_msgs::Imu> raw;
  std::vector<imu_lab::ImuIncrement> increments;
  std::vector<imu_lab::ImuTruth> truth;
  std::vector<sensor_msgs::Temperature> temperatures;
};

int expected_count() {
  int count = 400;
  ros::param::param("~sample_count", count, 400);
  return count;
}

double expected_rate_hz() {
  double rate = 200.0;
  ros::param::param("~expected_rate_hz", rate, 200.0);
  return rate;
}

Collected collect(std::size_t count) {
  ros::NodeHandle node;
  Collected collected;
  const std::size_t queue = 10 * count;
  auto raw = node.subscribe<sensor_msgs::Imu>("imu/raw", queue, [&](const sensor_msgs::Imu::ConstPtr& m) {
    if (collected.raw.size() < count) collected.raw.push_back(*m);
  });
  auto increment =
      node.subscribe<imu_lab::ImuIncrement>("imu/increment", queue, [&](const imu_lab::ImuIncrement::ConstPtr& m) {
        if (collected.increments.size() < count) collected.increments.push_back(*m);
      });
  auto truth = node.subscribe<imu_lab::ImuTruth>("imu/truth", queue, [&](const imu_lab::ImuTruth::ConstPtr& m) {
    if (collected.truth.size() < count) collected.truth.push_back(*m);
  });
  auto temperature = node.subscribe<sensor_msgs::Temperature>("imu/temperature", queue,
                                                              [&](const sensor_msgs::Temperature::ConstPtr& m) {
                                                                if (collected.temperatures.size() < count)
                                                                  collected.temperatures.push_back(*m);
                                                              });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(120.0);  // generous for loaded CI
  while (ros::ok() && ros::WallTime::now() < deadline &&
         std::min({collected.raw.size(), collected.increments.size(), collected.truth.size(),
                   collected.temperatures.size()}) < count) {
    ros::spinOnce();
    ros::WallDuration(0.002).sleep();
  }
  return collected;
}

TEST(ImuEmulatorNode, PublishesAtTheConfiguredRateWithStrictlyIncreasingStamps) {
  const std::size_t count = expected_count();
  const double interval_s = 1.0 / expected_rate_hz();
  const Collected collected = collect(count);
  ASSERT_EQ(collected.raw.size(), count) << "imu/raw did not deliver " << count << " messages in time";
  ASSERT_EQ(collected.increments.size(), count);
  ASSERT_EQ(collected.truth.size(), count);
  ASSERT_EQ(collected.temperatures.size(), count);

  // Consecutive messages (no drops on a large queue) one interval apart, to the nanosecond.
  std::vector<double> intervals_s;
  for (std::size_t i = 1; i < count; ++i) {
    const double dt = (collected.raw[i].header.stamp - collected.raw[i - 1].header.stamp).toSec();
    ASSERT_GT(dt, 0.0) << "stamps not strictly increasing at message " << i;
    intervals_s.push_back(dt);
  }
  for (double dt : intervals_s) EXPECT_NEAR(dt, interval_s, 2e-9);
  const double measured_rate_hz =
      (count - 1) / (collected.raw.back().header.stamp - collected.raw.front().header.stamp).toSec();
  EXPECT_NEAR(measured_rate_hz, expected_rate_hz(), 1e-6 * expected_rate_hz());

  // The other topics describe the same samples. Subscriptions connect at slightly different
  // moments, so messages are matched by stamp over the span all four topics cover.
  std::map<ros::Time, const imu_lab::ImuIncrement*> increment_by_stamp;
  for (const auto& m : collected.increments) increment_by_stamp[m.header.stamp] = &m;
  std::map<ros::Time, const imu_lab::ImuTruth*> truth_by_stamp;
  for (const auto& m : collected.truth) truth_by_stamp[m.header.stamp] = &m;
  const ros::Time common_start =
      std::max({collected.raw.front().header.stamp, collected.increments.front().header.stamp,
                collected.truth.front().header.stamp});
  const ros::Time common_end = std::min({collected.raw.back().header.stamp, collected.increments.back().header.stamp,
                                         collected.truth.back().header.stamp});
  std::size_t matched = 0;
  for (const auto& raw : collected.raw) {
    if (raw.header.stamp < common_start || raw.header.stamp > common_end) continue;
    ASSERT_EQ(increment_by_stamp.count(raw.header.stamp), 1u) << "no increment for stamp " << raw.header.stamp;
    ASSERT_EQ(truth_by_stamp.count(raw.header.stamp), 1u) << "no truth for stamp " << raw.header.stamp;
    const auto& increment = *increment_by_stamp[raw.header.stamp];
    EXPECT_NEAR(increment.interval_s, interval_s, 1e-12);
    EXPECT_NEAR(increment.delta_angle_rad.x, raw.angular_velocity.x * interval_s, 1e-15);
    EXPECT_NEAR(increment.delta_velocity_m_s.z, raw.linear_acceleration.z * interval_s, 1e-12);
    EXPECT_EQ(raw.header.frame_id, "imu_link");
    EXPECT_EQ(raw.orientation_covariance[0], -1.0);
    EXPECT_GT(raw.angular_velocity_covariance[0], 0.0);
    ++matched;
  }
  EXPECT_GT(matched, count / 2);
  // A level IMU at rest: the vertical specific force is about +g (REP-103: z up).
  double mean_z = 0.0;
  for (const auto& raw : collected.raw) mean_z += raw.linear_acceleration.z / count;
  EXPECT_NEAR(mean_z, 9.8, 0.1);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "emulator_stream_check");
  return RUN_ALL_TESTS();
}
