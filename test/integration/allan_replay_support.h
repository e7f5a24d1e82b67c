// Shared by the allan_monitor rostest checkers: an emulated bag, `rosbag play` of it, allan_monitor
// processes started and stopped by the checker, the node's latest curves, and the comparison of
// the node's report CSVs with the allan tool's computation on the same bag.
#pragma once

#include <gtest/gtest.h>
#include <imu_lab/AllanDeviation.h>
#include <ros/ros.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/io/stability_table.h"
#include "imu_lab/ros_io/bag/allan_bag_pass.h"
#include "imu_lab/ros_io/bag/allan_report.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "imu_lab/ros_io/bag/emulated_bag.h"

extern char** environ;

namespace imu_lab {
namespace replay_check {

constexpr double kEmulatedRate_hz = 200.0;
constexpr double kEmulatedStart_s = 1000.0;

// A tactical MEMS at rest, /imu/raw only; returns the message count.
inline std::size_t write_emulated_imu_bag(const std::string& path, double duration_s) {
  const auto profile = emulator::load_sensor_profile(ros_io::resolve_config("sensors", "tactical_mems"));
  const auto scenario = emulator::load_scenario(ros_io::resolve_config("scenarios", "static"));
  emulator::EmulatorSettings settings;
  settings.rate_hz = kEmulatedRate_hz;
  settings.start_time_s = kEmulatedStart_s;
  settings.seed = 11;
  emulator::ImuEmulator emulator(profile, scenario, settings);
  ros_io::EmulatedBagOptions options;
  options.duration_s = duration_s;
  options.write_temperature = options.write_truth = options.write_increments = false;
  return ros_io::write_emulated_bag(emulator, options, path);
}

inline std::string scratch_directory() {
  char pattern[] = "/tmp/imu_lab_replay_XXXXXX";
  const char* made = ::mkdtemp(pattern);
  return made != nullptr ? made : "/tmp";
}

// Plays /imu/raw of the bag into the graph, as fast as `rate_factor` allows, with a queue that
// never drops and only once the monitor has subscribed. Returns rosbag's exit status.
inline int play_bag(const std::string& bag, const std::string& options) {
  const std::string command = "rosbag play " + bag + " --clock --quiet --queue=1000000 --wait-for-subscribers " +
                              options + " --topics /imu/raw > /dev/null";
  return std::system(command.c_str());
}

// `rosrun imu_lab allan_monitor` with command-line parameters, stopped (SIGINT: a clean shutdown)
// when it goes out of scope, so a failed assertion leaves no node behind. rosrun execs the node,
// so the pid is the node's.
class MonitorProcess {
 public:
  MonitorProcess(const std::string& name, const std::vector<std::string>& parameters) {
    std::vector<std::string> arguments = {"rosrun", "imu_lab", "allan_monitor", "__name:=" + name};
    arguments.insert(arguments.end(), parameters.begin(), parameters.end());
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    argv.push_back(nullptr);
    if (::posix_spawnp(&pid_, "rosrun", nullptr, nullptr, argv.data(), environ) != 0) pid_ = -1;
  }
  ~MonitorProcess() { stop(SIGINT); }
  MonitorProcess(const MonitorProcess&) = delete;
  MonitorProcess& operator=(const MonitorProcess&) = delete;

  bool started() const { return pid_ > 0; }
  void stop(int signal_number) {
    if (pid_ <= 0) return;
    ::kill(pid_, signal_number);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }

 private:
  pid_t pid_ = -1;
};

// The node's latest gyro curves (it publishes every statistic it is asked for on one topic).
class LatestCurves {
 public:
  explicit LatestCurves(ros::NodeHandle& node) {
    subscriber_ = node.subscribe<imu_lab::AllanDeviation>("/allan/gyro", 100,
                                                          [this](const imu_lab::AllanDeviation::ConstPtr& message) {
                                                            if (message->statistic == "oadev") latest_ = *message;
                                                          });
  }
  // Waits (wall clock, generous for a loaded machine) until the node reports `samples`.
  bool wait_for_samples(std::uint64_t samples, double timeout_s) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
    while (ros::ok() && ros::WallTime::now() < deadline && latest_.samples < samples) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
    return latest_.samples == samples;
  }
  const imu_lab::AllanDeviation& latest() const { return latest_; }

 private:
  ros::Subscriber subscriber_;
  imu_lab::AllanDeviation latest_;
};

// The allan tool's computation on the bag, with its default options.
inline allan::StreamingSnapshot tool_result(const std::string& bag) {
  ros_io::AllanBagPassOptions options;
  options.topic = "/imu/raw";
  return ros_io::run_allan_bag_pass(bag, options).snapshot;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Largest |node / tool - 1| over every point of every statistic's CSV; fails the test on a
// missing file or a different set of points.
inline double max_relative_difference(const std::string& report_dir, const allan::StreamingSnapshot& tool) {
  double largest = 0.0;
  for (const allan::Statistic statistic : allan::kStreamingStatistics) {
    const std::string path = report_dir + "/" + allan::statistic_name(statistic) + ".csv";
    const auto node_curves = io::parse_stability_csv(read_text(path));
    const auto tool_curves = ros_io::channel_curves(tool, statistic);
    EXPECT_EQ(node_curves.size(), tool_curves.size()) << path;
    for (std::size_t c = 0; c < std::min(node_curves.size(), tool_curves.size()); ++c) {
      const auto& a = node_curves[c].points;
      const auto& b = tool_curves[c].points;
      EXPECT_EQ(a.size(), b.size()) << path << " " << tool_curves[c].name;
      EXPECT_GT(b.size(), 10u) << path;
      for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        EXPECT_EQ(a[i].averaging_factor, b[i].averaging_factor) << path;
        largest = std::max(largest, std::abs(a[i].deviation / b[i].deviation - 1.0));
      }
    }
  }
  return largest;
}

}  // namespace replay_check
}  // namespace imu_lab
