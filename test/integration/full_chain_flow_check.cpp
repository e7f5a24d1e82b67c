// rostest checker for full_chain_nodelets.test: every stage of launch/full_chain.launch publishes
// (the thermal and calibration outputs, the navigator's alignment and odometry, the Allan monitor's
// curves), counted over ROS until each has min_messages or the time-out. Counts only, never rates.
#include <gtest/gtest.h>
#include <imu_lab/Alignment.h>
#include <imu_lab/AllanDeviation.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>

#include <map>
#include <string>

namespace {

TEST(FullChainFlow, EveryStagePublishes) {
  ros::NodeHandle node;
  const int min_messages = ros::param::param("~min_messages", 100);
  const double timeout_s = ros::param::param("~timeout_s", 90.0);
  std::map<std::string, int> received = {
      {"/imu/thermal", 0}, {"/imu/corrected", 0}, {"/nav/odometry", 0}, {"/nav/alignment", 0}, {"/allan/gyro", 0}};
  auto count = [&](const std::string& topic) { return [&received, topic](const auto&) { ++received[topic]; }; };
  auto thermal = node.subscribe<sensor_msgs::Imu>("/imu/thermal", 10000, count("/imu/thermal"));
  auto corrected = node.subscribe<sensor_msgs::Imu>("/imu/corrected", 10000, count("/imu/corrected"));
  auto odometry = node.subscribe<nav_msgs::Odometry>("/nav/odometry", 10000, count("/nav/odometry"));
  auto alignment = node.subscribe<imu_lab::Alignment>("/nav/alignment", 10, count("/nav/alignment"));
  auto allan = node.subscribe<imu_lab::AllanDeviation>("/allan/gyro", 100, count("/allan/gyro"));
  // The latched alignment and the once-a-second curves need one message; the streams min_messages.
  auto done = [&] {
    return received["/imu/thermal"] >= min_messages && received["/imu/corrected"] >= min_messages &&
           received["/nav/odometry"] >= min_messages && received["/nav/alignment"] >= 1 && received["/allan/gyro"] >= 1;
  };
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
  while (ros::ok() && ros::WallTime::now() < deadline && !done()) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  for (const auto& [topic, messages] : received)
    std::printf("full_chain_flow_check: %s: %d messages\n", topic.c_str(), messages);
  EXPECT_TRUE(done()) << "a stage of the chain published too little within " << timeout_s << " s";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "full_chain_flow_check");
  ros::NodeHandle node;
  return RUN_ALL_TESTS();
}
