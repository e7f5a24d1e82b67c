// rostest checker for strapdown_navigator: emulates an IMU into a bag (emulate_arguments), runs the
// navigate tool on it for the reference solution, then plays the bag with `rosbag play --clock`
// into the node and checks that every published odometry equals the tool's solution at the same
// stamp, that tf2 serves world -> imu_link, and that the alignment (alignment_method) is latched.
// With single_channel_velocity_east_m_s (a start at that east velocity on the non-rotating sphere,
// at rest) every odometry's position must also follow the textbook's single-channel error
// (v0 / w0) sin(w0 t) east, nothing north, within 2 % of its peak (Fomichev 2022 eq. 23).
// Counts and generous time-outs only, never wall-clock rates.
#include <gtest/gtest.h>
#include <imu_lab/Alignment.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <stdlib.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "connection_support.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/nav/earth_model.h"
#include "imu_lab/pipeline/navigation_csv.h"
#include "imu_lab/pipeline/navigation_settings.h"
#include "imu_lab/ros_io/msg/navigation_messages.h"

namespace {

std::string private_string(const std::string& name) {
  std::string value;
  ros::param::get("~" + name, value);
  return value;
}

void run_or_fail(const std::string& command) { ASSERT_EQ(std::system(command.c_str()), 0) << "failed: " << command; }

TEST(StrapdownNavigatorNode, PublishesTheNavigateToolsSolutionAndTheTransform) {
  char pattern[] = "/tmp/imu_lab_navigator_check_XXXXXX";
  const std::string directory = ::mkdtemp(pattern);
  const std::string bag = directory + "/static.bag";
  const std::string reference_csv = directory + "/reference.csv";
  run_or_fail("rosrun imu_lab emulate " + private_string("emulate_arguments") + " --out " + bag + " > " + directory +
              "/emulate.log 2>&1");
  run_or_fail("rosrun imu_lab navigate " + bag + " " + private_string("navigate_arguments") + " --out " +
              reference_csv + " > " + directory + "/navigate.log 2>&1");
  const auto reference = imu_lab::pipeline::read_trajectory_csv(reference_csv);
  ASSERT_GT(reference.size(), 100u);

  ros::NodeHandle node;
  std::map<ros::Time, nav_msgs::Odometry> odometry;
  std::vector<imu_lab::Alignment> alignments;
  auto odometry_subscriber = node.subscribe<nav_msgs::Odometry>(
      "nav/odometry", 100000, [&](const nav_msgs::Odometry::ConstPtr& m) { odometry[m->header.stamp] = *m; });
  auto alignment_subscriber = node.subscribe<imu_lab::Alignment>(
      "nav/alignment", 10, [&](const imu_lab::Alignment::ConstPtr& m) { alignments.push_back(*m); });
  tf2_ros::Buffer buffer(ros::Duration(600.0));
  tf2_ros::TransformListener listener(buffer);

  // The node's input subscription makes --wait-for-subscribers start the playback.
  ASSERT_TRUE(imu_lab::connection_check::play_and_collect(
      bag, private_string("play_arguments"), directory + "/play.log", "/strapdown_navigator", "/nav/odometry",
      [&] { return odometry.size() >= reference.size(); }, 240.0));
  ASSERT_EQ(odometry.size(), reference.size()) << "the node did not publish one odometry per tool solution in time";

  // Same input, same NavigationSession: the same numbers, to round-off.
  double worst_position_m = 0.0;
  double worst_attitude_rad = 0.0;
  for (const auto& expected : reference) {
    const auto found = odometry.find(imu_lab::ros_io::to_ros_time(expected.stamp_ns));
    ASSERT_NE(found, odometry.end()) << "no odometry at " << imu_lab::format_stamp_s(expected.stamp_ns);
    const auto& pose = found->second.pose.pose;
    const Eigen::Vector3d position(pose.position.x, pose.position.y, pose.position.z);
    const Eigen::Quaterniond q(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z);
    worst_position_m = std::max(worst_position_m, (position - expected.position_enu_m).norm());
    worst_attitude_rad = std::max(worst_attitude_rad, q.angularDistance(expected.q_body_to_enu));
    EXPECT_EQ(found->second.header.frame_id, "world");
    EXPECT_EQ(found->second.child_frame_id, "imu_link");
  }
  std::printf("[navigator_check] %zu odometry messages vs the tool: worst position %.3g m, attitude %.3g rad\n",
              odometry.size(), worst_position_m, worst_attitude_rad);
  EXPECT_LT(worst_position_m, 1e-9);
  EXPECT_LT(worst_attitude_rad, 1e-12);

  // tf2: world -> imu_link at the last solution's stamp is that solution's pose.
  const auto& last = odometry.rbegin()->second;
  std::string why;
  ASSERT_TRUE(buffer.canTransform("world", "imu_link", last.header.stamp, ros::Duration(10.0), &why)) << why;
  const auto transform = buffer.lookupTransform("world", "imu_link", last.header.stamp);
  EXPECT_NEAR(transform.transform.translation.x, last.pose.pose.position.x, 1e-12);
  EXPECT_NEAR(transform.transform.translation.y, last.pose.pose.position.y, 1e-12);
  EXPECT_NEAR(transform.transform.rotation.w, last.pose.pose.orientation.w, 1e-12);
  EXPECT_NEAR(transform.transform.rotation.z, last.pose.pose.orientation.z, 1e-12);

  ASSERT_EQ(alignments.size(), 1u);
  std::string method = "gyrocompass";
  ros::param::get("~alignment_method", method);
  EXPECT_EQ(alignments[0].method, method);
  EXPECT_EQ(alignments[0].header.stamp, odometry.begin()->first);  // navigation starts where alignment ends

  double v0_m_s = 0.0;
  if (!ros::param::get("~single_channel_velocity_east_m_s", v0_m_s)) return;
  const double w0 =
      imu_lab::nav::EarthModel(imu_lab::pipeline::parse_earth_model("sphere", "sphere")).schuler_rate_rad_s();
  const double peak_m = std::abs(v0_m_s) / w0;
  const ros::Time start = odometry.begin()->first;
  double worst_m = 0.0, last_t = 0.0;
  for (const auto& [stamp, message] : odometry) {
    last_t = (stamp - start).toSec();
    const auto& p = message.pose.pose.position;  // the truth stays at the origin
    const double deviation_m = std::hypot(p.x - v0_m_s / w0 * std::sin(w0 * last_t), p.y);
    worst_m = std::max(worst_m, deviation_m);
    ASSERT_LE(deviation_m, 0.02 * peak_m) << "at t = " << last_t << " s";
  }
  std::printf(
      "[navigator_check] single channel, v0 %.3g m/s: peak %.1f m, worst deviation %.3g m (%.3g %%) over %.0f s\n",
      v0_m_s, peak_m, worst_m, 100.0 * worst_m / peak_m, last_t);
  EXPECT_GE(last_t, 0.99 * 2.0 * M_PI / w0);  // at least a whole Schuler period
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "navigator_check");
  return RUN_ALL_TESTS();
}
