// rostest checker for allan_monitor (launched by allan_monitor_replay.test): plays an emulated bag
// with `rosbag play --clock` into the node, checks the node counted every message, asks for its
// report (~write_report) and compares every curve with the allan tool's on the same bag.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/Imu.h>
#include <std_srvs/Trigger.h>
#include <yaml-cpp/yaml.h>

#include <map>

#include "allan_replay_support.h"
#include "connection_support.h"

namespace {

using namespace imu_lab::replay_check;

constexpr double kDuration_s = 150.0;

TEST(AllanMonitorReplay, CurvesEqualTheToolsOnTheSameBag) {
  ros::NodeHandle node;
  std::string report_dir;
  ASSERT_TRUE(ros::param::get("/allan_monitor/report_dir", report_dir));
  const std::string bag = scratch_directory() + "/replay.bag";
  const std::size_t messages = write_emulated_imu_bag(bag, kDuration_s);
  LatestCurves curves(node);
  ASSERT_TRUE(ros::service::waitForService("/allan_monitor/write_report", ros::Duration(60.0)));

  ASSERT_EQ(play_bag(bag, "--rate=25"), 0);
  ASSERT_TRUE(curves.wait_for_samples(messages, 60.0))
      << "the node reports " << curves.latest().samples << " of the bag's " << messages << " messages";

  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call("/allan_monitor/write_report", trigger));
  ASSERT_TRUE(trigger.response.success) << trigger.response.message;

  const auto tool = tool_result(bag);
  const double difference = max_relative_difference(report_dir, tool);
  std::printf("allan_monitor vs allan tool on %zu messages: max relative difference %.3g over 9 statistics\n", messages,
              difference);
  EXPECT_LE(difference, 1e-12);

  // The published curve is the same as the report's.
  const auto& published = curves.latest();
  const auto& expected = tool.curve(imu_lab::allan::Statistic::kOverlappingAllan, 0);
  ASSERT_EQ(published.tau_s.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(published.axes[0].deviation[i] / expected[i].deviation, 1.0, 1e-12);
  }
  EXPECT_EQ(published.unit, "rad/s");
  EXPECT_NEAR(published.tau0_s, 1.0 / kEmulatedRate_hz, 1e-12);

  const YAML::Node summary = YAML::LoadFile(report_dir + "/allan_summary.yaml");
  EXPECT_EQ(summary["topic"].as<std::string>(), "/imu/raw");
  EXPECT_EQ(summary["samples"].as<std::size_t>(), messages);
  EXPECT_EQ(summary["out_of_order"]["count"].as<int>(), 0);
  EXPECT_EQ(summary["duplicates"]["count"].as<int>(), 0);
}

// A node never dies on its input. Finite values beyond +-1e100 (1e308 rad/s made the snapshot's
// noise-type estimate throw through spin(): FATAL) and samples whose gyro triad is marked as not
// provided are left out of their channels, counted and reported on /diagnostics; the curves keep
// coming. Runs after the replay above, on stamps after the bag's.
TEST(AllanMonitorReplay, ExtremeValuesAndMissingTriadsAreLeftOutAndReported) {
  ros::NodeHandle node;
  LatestCurves curves(node);
  std::map<std::string, std::string> totals;  // the monitor's diagnostic values
  auto diagnostics = node.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 100, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& array) {
        for (const auto& status : array->status) {
          if (status.hardware_id != "allan_monitor") continue;
          for (const auto& pair : status.values) totals[pair.key] = pair.value;
        }
      });
  auto publisher = node.advertise<sensor_msgs::Imu>("/imu/raw", 10000);
  ASSERT_TRUE(imu_lab::connection_check::wait_until([&] { return publisher.getNumSubscribers() > 0; }, 60.0));
  ASSERT_TRUE(imu_lab::connection_check::wait_until(
      [&] {
        ros::spinOnce();
        return curves.latest().samples > 0;
      },
      60.0));
  const std::uint64_t before = curves.latest().samples;
  constexpr int kSamples = 2000;
  for (int k = 1; k <= kSamples; ++k) {
    sensor_msgs::Imu message;
    message.header.stamp = ros::Time(kEmulatedStart_s + static_cast<double>(before + k) / kEmulatedRate_hz);
    message.angular_velocity.x = 1e-4 * ((k % 7) - 3);
    message.linear_acceleration.z = 9.81 + 1e-3 * ((k % 5) - 2);
    if (k == 500) message.angular_velocity.y = 1e308;
    if (k == 1500) message.linear_acceleration.x = -1e308;
    if (k == 1000) message.angular_velocity_covariance[0] = -1.0;
    publisher.publish(message);
  }
  ASSERT_TRUE(curves.wait_for_samples(before + kSamples, 60.0))
      << "the node stopped at " << curves.latest().samples << " samples (it used to die on 1e308)";
  // The node's diagnostics follow the simulated clock, which stopped with the bag: this checker
  // moves it on.
  auto clock = node.advertise<rosgraph_msgs::Clock>("/clock", 10);
  rosgraph_msgs::Clock now;
  now.clock = ros::Time(kEmulatedStart_s + 1000.0);
  ASSERT_TRUE(imu_lab::connection_check::wait_until(
      [&] {
        now.clock += ros::Duration(0.2);
        clock.publish(now);
        ros::spinOnce();
        return totals["samples with a value beyond +-1e100"] == "2" &&
               totals["samples without a triad (covariance[0] = -1)"] == "1";
      },
      30.0))
      << "beyond 1e100: " << totals["samples with a value beyond +-1e100"]
      << ", without a triad: " << totals["samples without a triad (covariance[0] = -1)"];
  for (double deviation : curves.latest().axes[1].deviation) EXPECT_TRUE(std::isfinite(deviation));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "allan_monitor_replay_check");
  ros::NodeHandle keep_alive;
  return RUN_ALL_TESTS();
}
