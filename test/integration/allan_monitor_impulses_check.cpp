// rostest checker for allan_monitor's impulse and level-shift screens (launched by
// allan_monitor_impulses.test): an emulated bag with a knock 30 s in and a tilt from 340 s to 380 s
// is played into the node with `rosbag play --clock`. The node must warn about the knock on
// /diagnostics with its count, list the knock and the tilt's two steps in its report's summary with
// the stamps the allan tool finds, split the runs there and end with the tool's curves.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <rosbag/bag.h>
#include <std_srvs/Trigger.h>
#include <yaml-cpp/yaml.h>

#include "allan_replay_support.h"
#include "imu_lab/ros_io/msg/emulator_messages.h"

namespace {

using namespace imu_lab::replay_check;

constexpr double kDuration_s = 420.0;
constexpr double kKnock_s = 30.0;  // from the first stamp
// A tilt after the level-shift screen's 300 s of scale: accelerometer x and y move by 0.03 and
// -0.02 m/s^2 (tens of the screen's scales at this noise) and back.
constexpr double kTiltStart_s = 340.0, kTiltEnd_s = 380.0;

// The emulated tactical MEMS at rest, with a knock: accelerometer z rings at 0.5 m/s^2 (some
// hundreds of its noise) decaying over 0.1 s, gyro x at 0.01 rad/s, and a bias step of 1 mm/s^2;
// and the tilt.
std::size_t write_knocked_bag(const std::string& path) {
  const auto profile =
      imu_lab::emulator::load_sensor_profile(imu_lab::ros_io::resolve_config("sensors", "tactical_mems"));
  const auto scenario = imu_lab::emulator::load_scenario(imu_lab::ros_io::resolve_config("scenarios", "static"));
  imu_lab::emulator::EmulatorSettings settings;
  settings.rate_hz = kEmulatedRate_hz;
  settings.start_time_s = kEmulatedStart_s;
  settings.seed = 12;
  imu_lab::emulator::ImuEmulator emulator(profile, scenario, settings);
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  const double interval_s = 1.0 / kEmulatedRate_hz;
  const auto count = static_cast<std::size_t>(kDuration_s * kEmulatedRate_hz);
  for (std::size_t n = 1; n <= count; ++n) {
    auto message = imu_lab::ros_io::to_messages(emulator.next(), interval_s, "imu_link").raw;
    const ros::Time stamp = message.header.stamp;
    const double t = (n - 1) * interval_s - kKnock_s;
    if (t >= 0.0) {
      const double ringing = std::exp(-t / 0.1) * std::cos(2.0 * M_PI * 12.0 * t);
      message.linear_acceleration.z += 1e-3 + 0.5 * ringing;
      message.angular_velocity.x += 0.01 * ringing;
    }
    if (t + kKnock_s >= kTiltStart_s && t + kKnock_s < kTiltEnd_s) {
      message.linear_acceleration.x += 0.03;
      message.linear_acceleration.y -= 0.02;
    }
    bag.write("/imu/raw", stamp, message);
  }
  bag.close();
  return count;
}

// The allan_monitor status of every /diagnostics message seen: its worst level and its values.
class MonitorDiagnostics {
 public:
  explicit MonitorDiagnostics(ros::NodeHandle& node) {
    subscriber_ = node.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 100, [this](const diagnostic_msgs::DiagnosticArray::ConstPtr& array) {
          for (const auto& status : array->status) {
            if (status.name.find("allan monitor") == std::string::npos) continue;
            if (status.level == diagnostic_msgs::DiagnosticStatus::WARN &&
                status.message.find("knocks or spikes") != std::string::npos) {
              warned_ = true;
            }
            for (const auto& value : status.values) {
              if (value.key == "impulse events (knocks, spikes)") events_ = value.value;
            }
          }
        });
  }
  // Waits (wall clock, generous for a loaded machine) for a status counting `events`.
  bool wait_for_events(const std::string& events, double timeout_s) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
    while (ros::ok() && ros::WallTime::now() < deadline && events_ != events) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
    return events_ == events;
  }
  bool warned() const { return warned_; }

 private:
  ros::Subscriber subscriber_;
  std::string events_;
  bool warned_ = false;
};

TEST(AllanMonitorImpulses, AKnockAndATiltAreListedAndSplitTheRunsAsTheToolDoes) {
  ros::NodeHandle node;
  std::string report_dir;
  ASSERT_TRUE(ros::param::get("/allan_monitor/report_dir", report_dir));
  const std::string bag = scratch_directory() + "/knocked.bag";
  const std::size_t messages = write_knocked_bag(bag);
  imu_lab::ros_io::AllanBagPassOptions options;
  options.topic = "/imu/raw";
  const auto tool = imu_lab::ros_io::run_allan_bag_pass(bag, options);
  ASSERT_EQ(tool.impulses.event_count, 1);
  const auto& expected = tool.impulses.events.front();
  ASSERT_EQ(tool.level_shifts.event_count, 2);
  LatestCurves curves(node);
  MonitorDiagnostics diagnostics(node);
  ASSERT_TRUE(ros::service::waitForService("/allan_monitor/write_report", ros::Duration(60.0)));

  ASSERT_EQ(play_bag(bag, "--rate=25"), 0);
  // The curves cover every sample received but those of the event's window.
  const auto engine_samples = static_cast<std::uint64_t>(tool.snapshot.timing.input_sample_count);
  ASSERT_TRUE(curves.wait_for_samples(engine_samples, 60.0))
      << "the node reports " << curves.latest().samples << " samples, the tool " << engine_samples;
  ASSERT_TRUE(diagnostics.wait_for_events("1", 30.0)) << "no allan_monitor status counting one impulse event";
  EXPECT_TRUE(diagnostics.warned()) << "the event's second of diagnostics must be a warning naming it";

  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call("/allan_monitor/write_report", trigger));
  ASSERT_TRUE(trigger.response.success) << trigger.response.message;

  const YAML::Node summary = YAML::LoadFile(report_dir + "/allan_summary.yaml");
  const YAML::Node screen = summary["impulse_screen"];
  EXPECT_EQ(screen["events"]["count"].as<int>(), 1);
  ASSERT_EQ(screen["listed_events"].size(), 1u);
  const YAML::Node event = screen["listed_events"][0];
  EXPECT_EQ(event["onset_stamp_ns"].as<std::int64_t>(), expected.onset_stamp_ns);
  EXPECT_EQ(event["window_stamps_ns"][0].as<std::int64_t>(), expected.start_stamp_ns);
  EXPECT_EQ(event["window_stamps_ns"][1].as<std::int64_t>(), expected.end_stamp_ns);
  EXPECT_NEAR(event["onset_from_start_s"].as<double>(), kKnock_s, 1.0 / kEmulatedRate_hz);
  EXPECT_EQ(event["peak_channel"].as<std::string>(), "accel_z");
  EXPECT_EQ(summary["samples"].as<std::int64_t>(), tool.snapshot.timing.input_sample_count);
  EXPECT_EQ(summary["samples"].as<std::int64_t>() + screen["dropped_samples"].as<std::int64_t>(),
            static_cast<std::int64_t>(messages));
  // The knock splits every channel; the tilt's two steps the accelerometer's only.
  EXPECT_EQ(summary["channels"]["gyro_x"]["segments"].as<int>(), 2);
  EXPECT_EQ(summary["channels"]["accel_z"]["segments"].as<int>(), 4);
  const YAML::Node shifts = summary["level_shift_screen"];
  EXPECT_EQ(shifts["shifts"]["count"].as<int>(), 2);
  ASSERT_EQ(shifts["listed_shifts"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(shifts["listed_shifts"][i]["step_stamp_ns"].as<std::int64_t>(),
              tool.level_shifts.events[i].step_stamp_ns);
    EXPECT_NEAR(shifts["listed_shifts"][i]["step_from_start_s"].as<double>(), i == 0 ? kTiltStart_s : kTiltEnd_s, 0.5);
  }
  EXPECT_EQ(summary["channels"]["accel_x"]["non_finite_samples"].as<int>(), 0) << "the screen's NaNs are its own";
  const double difference = max_relative_difference(report_dir, tool.snapshot);
  std::printf(
      "allan_monitor vs allan tool on a knocked bag of %zu messages: event at %.3f s, max relative "
      "difference %.3g over 9 statistics\n",
      messages, event["onset_from_start_s"].as<double>(), difference);
  EXPECT_LE(difference, 1e-12);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "allan_monitor_impulses_check");
  ros::NodeHandle keep_alive;
  return RUN_ALL_TESTS();
}
