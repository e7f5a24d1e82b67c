// rostest checker for calibration_corrector: emulates a bag, plays it with `rosbag play --clock`
// into the node, and checks that the node publishes one corrected sample per input sample, with
// the same stamps, equal to the core library's correction (ImuCalibration::correct). Counts and
// generous time-outs only, never wall-clock rates.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <stdlib.h>

#include <cstdio>
#include <map>
#include <string>

#include "connection_support.h"
#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"

namespace {

std::string private_string(const std::string& name) {
  std::string value;
  ros::param::get("~" + name, value);
  return value;
}

Eigen::Vector3d vector_of(const geometry_msgs::Vector3& v) { return Eigen::Vector3d(v.x, v.y, v.z); }

TEST(CalibrationCorrectorNode, PublishesTheCoreCorrectionOfEverySample) {
  char pattern[] = "/tmp/imu_lab_corrector_check_XXXXXX";
  const std::string directory = ::mkdtemp(pattern);
  const std::string bag = directory + "/calibration.bag";
  const std::string emulate = "rosrun imu_lab emulate " + private_string("emulate_arguments") + " --out " + bag +
                              " > " + directory + "/emulate.log 2>&1";
  ASSERT_EQ(std::system(emulate.c_str()), 0) << "failed: " << emulate;
  const auto calibration = imu_lab::calib::load_calibration(private_string("calibration_file"));
  std::map<std::int64_t, imu_lab::io::ImuRecord> inputs;
  imu_lab::ros_io::for_each_imu(bag, "/imu/raw",
                                [&](const imu_lab::io::ImuRecord& record) { inputs[record.stamp_ns] = record; });
  ASSERT_GT(inputs.size(), 1000u);

  ros::NodeHandle node;
  std::map<std::int64_t, sensor_msgs::Imu> outputs;
  auto subscriber = node.subscribe<sensor_msgs::Imu>(
      "/imu/corrected", 100000,
      [&](const sensor_msgs::Imu::ConstPtr& m) { outputs[static_cast<std::int64_t>(m->header.stamp.toNSec())] = *m; });
  ASSERT_TRUE(imu_lab::connection_check::play_and_collect(
      bag, private_string("play_arguments"), directory + "/play.log", "/calibration_corrector", "/imu/corrected",
      [&] { return outputs.size() >= inputs.size(); }, 200.0));
  ASSERT_EQ(outputs.size(), inputs.size()) << "the node did not publish one corrected sample per input in time";

  double worst_rate_rad_s = 0.0, worst_force_m_s2 = 0.0, largest_change_m_s2 = 0.0;
  for (const auto& [stamp_ns, input] : inputs) {
    const auto found = outputs.find(stamp_ns);
    ASSERT_NE(found, outputs.end()) << "no corrected sample at " << stamp_ns << " ns";
    const auto expected = calibration.correct(input.angular_rate_rad_s, input.specific_force_m_s2);
    worst_rate_rad_s =
        std::max(worst_rate_rad_s, (vector_of(found->second.angular_velocity) - expected.angular_rate_rad_s).norm());
    worst_force_m_s2 = std::max(worst_force_m_s2,
                                (vector_of(found->second.linear_acceleration) - expected.specific_force_m_s2).norm());
    largest_change_m_s2 =
        std::max(largest_change_m_s2, (expected.specific_force_m_s2 - input.specific_force_m_s2).norm());
  }
  std::printf(
      "[calibration_corrector_check] %zu samples: worst difference from the core %.3g rad/s, %.3g m/s^2 "
      "(the correction itself moves the force by up to %.3g m/s^2)\n",
      outputs.size(), worst_rate_rad_s, worst_force_m_s2, largest_change_m_s2);
  EXPECT_LT(worst_rate_rad_s, 1e-15);
  EXPECT_LT(worst_force_m_s2, 1e-13);
  EXPECT_GT(largest_change_m_s2, 1e-3);  // the calibration really changes the data
}

// Like every node of the chain, the corrector drops a sample whose stamp is not after the previous
// one (it used to republish duplicates and out-of-order samples), and one whose gyro triad is
// marked as not provided (angular_velocity_covariance[0] = -1) instead of correcting its zeros, or
// whose value is beyond +-1e100 (1e308 m/s^2 was corrected and passed on).
TEST(CalibrationCorrectorNode, DropsDuplicateOutOfOrderAndIncompleteSamples) {
  ros::NodeHandle node;
  std::map<std::int64_t, int> published;  // stamp -> times published
  auto subscriber = node.subscribe<sensor_msgs::Imu>("/imu/corrected", 100, [&](const sensor_msgs::Imu::ConstPtr& m) {
    ++published[static_cast<std::int64_t>(m->header.stamp.toNSec())];
  });
  auto publisher = node.advertise<sensor_msgs::Imu>("/imu/raw", 100);
  using imu_lab::connection_check::sends;
  ASSERT_TRUE(imu_lab::connection_check::wait_until(
      [&] {
        return publisher.getNumSubscribers() > 0 &&
               sends("/calibration_corrector", "/imu/corrected", ros::this_node::getName());
      },
      60.0));
  // After the bag of the test before (the node's stamps only move forward).
  const std::int64_t start_ns = 2'000'000'000LL * 1'000'000'000LL;
  const std::int64_t step_ns = 10'000'000;
  const auto send = [&](std::int64_t stamp_ns, bool with_gyro, double force_z_m_s2 = 9.81) {
    sensor_msgs::Imu message;
    message.header.stamp.fromNSec(static_cast<std::uint64_t>(stamp_ns));
    message.angular_velocity.x = 1e-3;
    message.linear_acceleration.z = force_z_m_s2;
    if (!with_gyro) message.angular_velocity_covariance[0] = -1.0;
    publisher.publish(message);
  };
  send(start_ns, true);
  send(start_ns, true);                       // duplicate
  send(start_ns - 50 * step_ns, true);        // out of order
  send(start_ns + step_ns, false);            // no gyro data
  send(start_ns + 2 * step_ns, true, 1e308);  // beyond +-1e100
  send(start_ns + 3 * step_ns, true);         // the last: once it is in, everything before it is
  ASSERT_TRUE(imu_lab::connection_check::wait_until(
      [&] {
        ros::spinOnce();
        return published.count(start_ns + 3 * step_ns) > 0;
      },
      60.0));
  EXPECT_EQ(published[start_ns], 1) << "a duplicate stamp was republished";
  EXPECT_EQ(published.count(start_ns - 50 * step_ns), 0u) << "an out-of-order sample was republished";
  EXPECT_EQ(published.count(start_ns + step_ns), 0u) << "a sample without gyro data was corrected and republished";
  EXPECT_EQ(published.count(start_ns + 2 * step_ns), 0u) << "a sample with 1e308 m/s^2 was corrected and republished";
  EXPECT_EQ(published[start_ns + 3 * step_ns], 1);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "calibration_corrector_check");
  return RUN_ALL_TESTS();
}
