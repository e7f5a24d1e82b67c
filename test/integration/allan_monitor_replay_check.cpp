// rostest checker for allan_monitor (launched by allan_monitor_replay.test): plays an emulated bag
// with `rosbag play --clock` into the node, checks the node counted every message, asks for its
// report (~write_report) and compares every curve with the allan tool's on the same bag.
#include <std_srvs/Trigger.h>
#include <yaml-cpp/yaml.h>

#include "allan_replay_support.h"

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
  std::printf("allan_monitor vs allan tool on %zu messages: max relative difference %.3g over 9 statistics\n",
              messages, difference);
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

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "allan_monitor_replay_check");
  ros::NodeHandle keep_alive;
  return RUN_ALL_TESTS();
}
