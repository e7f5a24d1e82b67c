// rostest checker for allan_monitor's checkpoints (launched by allan_monitor_resume.test): a node
// fed the first part of an emulated bag is killed (no clean shutdown); a second node resumes from
// the last periodic checkpoint and is fed the rest of the bag from shortly before the
// checkpoint's stamp (`rosbag play -s`). It must skip the replayed stamps and end with the
// uninterrupted result: the allan tool's on the whole bag.
#include <std_srvs/Trigger.h>
#include <yaml-cpp/yaml.h>

#include <fstream>

#include "allan_replay_support.h"
#include "imu_lab/allan/streaming_allan.h"

namespace {

using namespace imu_lab::replay_check;

constexpr double kDuration_s = 150.0;
constexpr double kFirstPart_s = 80.0;
constexpr double kReplayedBeforeCheckpoint_s = 2.0;  // the second node must skip these

std::vector<std::string> monitor_parameters(const std::string& directory, const std::string& report, bool resume) {
  return {"_checkpoint_path:=" + directory + "/allan.checkpoint",
          "_checkpoint_period_s:=0.5",
          "_report_dir:=" + report,
          "_plot:=false",
          "_publish_period_s:=0.5",
          std::string("_resume:=") + (resume ? "true" : "false")};
}

// Waits (on the file, up to a generous limit) for a checkpoint holding at least `samples` (the node
// saves one every half second).
std::int64_t wait_for_checkpoint(const std::string& path, std::int64_t samples, std::int64_t* last_stamp_ns) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  while (ros::WallTime::now() < deadline) {
    if (std::ifstream(path).good()) {
      const auto engine = imu_lab::allan::StreamingAllan::load_checkpoint(path);
      if (engine.input_sample_count() >= samples) {
        *last_stamp_ns = engine.last_stamp_ns();
        return engine.input_sample_count();
      }
    }
    ros::WallDuration(0.1).sleep();
  }
  return -1;
}

TEST(AllanMonitorResume, RestartFromTheCheckpointEndsWithTheUninterruptedResult) {
  ros::NodeHandle node;
  const std::string directory = scratch_directory();
  const std::string bag = directory + "/resume.bag";
  const std::size_t messages = write_emulated_imu_bag(bag, kDuration_s);
  LatestCurves curves(node);

  MonitorProcess first("allan_monitor_first", monitor_parameters(directory, directory + "/first", false));
  ASSERT_TRUE(first.started());
  ASSERT_TRUE(ros::service::waitForService("/allan_monitor_first/write_report", ros::Duration(60.0)));
  ASSERT_EQ(play_bag(bag, "--rate=25 --duration=" + std::to_string(kFirstPart_s)), 0);
  const auto first_part = static_cast<std::int64_t>(kFirstPart_s * kEmulatedRate_hz * 0.9);
  std::int64_t checkpoint_stamp_ns = 0;
  ASSERT_GT(wait_for_checkpoint(directory + "/allan.checkpoint", first_part, &checkpoint_stamp_ns), 0)
      << "no checkpoint with " << first_part << " samples";
  first.stop(SIGKILL);  // a crash: whatever came after the last checkpoint is lost
  // The second node resumes from the checkpoint on disk now, which a loaded node may have written
  // after the one seen above (it was still working through its queue): the replay starts from its
  // stamp, whenever it was written.
  const auto checkpoint = imu_lab::allan::StreamingAllan::load_checkpoint(directory + "/allan.checkpoint");
  const std::int64_t checkpoint_samples = checkpoint.input_sample_count();
  checkpoint_stamp_ns = checkpoint.last_stamp_ns();

  const std::string report = directory + "/second";
  MonitorProcess second("allan_monitor_second", monitor_parameters(directory, report, true));
  ASSERT_TRUE(second.started());
  ASSERT_TRUE(ros::service::waitForService("/allan_monitor_second/write_report", ros::Duration(60.0)));
  const double bag_start_s = kEmulatedStart_s + 1.0 / kEmulatedRate_hz;
  const double replay_from_s = checkpoint_stamp_ns * 1e-9 - bag_start_s - kReplayedBeforeCheckpoint_s;
  ASSERT_EQ(play_bag(bag, "--rate=25 --start=" + std::to_string(replay_from_s)), 0);
  ASSERT_TRUE(curves.wait_for_samples(messages, 60.0))
      << "the resumed node reports " << curves.latest().samples << " of the bag's " << messages << " messages";

  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call("/allan_monitor_second/write_report", trigger));
  ASSERT_TRUE(trigger.response.success) << trigger.response.message;
  second.stop(SIGINT);

  const double difference = max_relative_difference(report, tool_result(bag));
  std::printf(
      "allan_monitor resumed from a checkpoint at sample %lld of %zu: max relative difference to the "
      "uninterrupted result %.3g over 9 statistics\n",
      static_cast<long long>(checkpoint_samples), messages, difference);
  EXPECT_LE(difference, 1e-12);

  const YAML::Node summary = YAML::LoadFile(report + "/allan_summary.yaml");
  EXPECT_EQ(summary["samples"].as<std::size_t>(), messages);
  EXPECT_EQ(summary["duplicates"]["count"].as<int>(), 0) << "replayed stamps must be skipped, not pushed";
  EXPECT_EQ(summary["out_of_order"]["count"].as<int>(), 0);
  EXPECT_NEAR(summary["skipped_before_checkpoint"].as<double>(), kReplayedBeforeCheckpoint_s * kEmulatedRate_hz,
              0.2 * kReplayedBeforeCheckpoint_s * kEmulatedRate_hz);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "allan_monitor_resume_check");
  ros::NodeHandle keep_alive;
  return RUN_ALL_TESTS();
}
