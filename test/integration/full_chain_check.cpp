// rostest checker for the whole chain (full_chain.test), as a user would run it:
//  1. emulates, with the `emulate` tool, a thermal test, a six-position calibration and a
//     navigation run of one sensor with thermal, bias, scale-factor and misalignment errors;
//  2. fits the thermal model (fit_thermal) and the calibration (fit_calibration) from their bags;
//  3. brings up launch/full_chain.launch on the navigation bag (rosbag play with /clock, rviz off),
//     starts the playback once every stage is connected, and collects /imu/corrected and
//     /nav/odometry;
//  4. navigates the raw bag with the navigate tool (the node's own NavigationSession, see
//     navigator_check.cpp) and compares both solutions with the bag's /imu/truth: the corrected
//     chain's largest horizontal position error must be at least 10x smaller than the raw one's;
//  5. checks the overlapping Allan variance of the corrected stream over the run's initial rest
//     against the sensor profile's analytic noise model (chi-squared bounds at each point's EDF,
//     Bonferroni-corrected over all points of the six channels: 99.7 % family-wise).
// Counts and generous time-outs only, never wall-clock rates.
#include <gtest/gtest.h>
#include <imu_lab/AllanDeviation.h>
#include <nav_msgs/Odometry.h>
#include <ros/master.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <signal.h>
#include <std_srvs/SetBool.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/LU>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "../unit/test_noise_avar_check.h"
#include "connection_support.h"
#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/emulator/analytic_profile_avar.h"
#include "imu_lab/emulator/sensor_profile.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/nav/local_enu.h"
#include "imu_lab/pipeline/navigation_csv.h"

namespace {

constexpr double kDegToRad = M_PI / 180.0;

std::string private_string(const std::string& name) {
  std::string value;
  if (!ros::param::get("~" + name, value)) ADD_FAILURE() << "missing private parameter " << name;
  return value;
}

double private_double(const std::string& name) {
  double value = 0.0;
  if (!ros::param::get("~" + name, value)) ADD_FAILURE() << "missing private parameter " << name;
  return value;
}

void run_or_fail(const std::string& command) { ASSERT_EQ(std::system(command.c_str()), 0) << "failed: " << command; }

// roslaunch in its own process group: SIGINT stops it and its nodes; the group is killed if not.
pid_t start_launch(const std::string& command) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    ::execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

void stop_launch(pid_t pid) {
  if (pid <= 0) return;
  ::kill(pid, SIGINT);
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (ros::WallTime::now() > deadline) {
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      ADD_FAILURE() << "roslaunch did not stop within 30 s of SIGINT";
      return;
    }
    ros::WallDuration(0.1).sleep();
  }
}

// Stops the launch however the test ends.
struct RunningLaunch {
  pid_t pid = -1;
  ~RunningLaunch() { stop(); }
  void stop() {
    stop_launch(pid);
    pid = -1;
  }
};

// Publisher and subscriber counts of a topic from the master (registrations, not connections).
std::pair<int, int> registrations(const std::string& topic) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", request, response, payload, true)) return {0, 0};
  auto count = [&](int kind) {
    for (int i = 0; i < payload[kind].size(); ++i) {
      if (static_cast<std::string>(payload[kind][i][0]) == topic) return payload[kind][i][1].size();
    }
    return 0;
  };
  return {count(0), count(1)};
}

struct CorrectedSample {
  std::int64_t stamp_ns = 0;
  Eigen::Vector3d angular_rate_rad_s, specific_force_m_s2;
};

// Largest horizontal position error against the truth over the stamps both have.
struct RunError {
  double max_horizontal_m = 0.0;
  double final_horizontal_m = 0.0;
  std::size_t compared = 0;
};

RunError horizontal_error(const std::map<std::int64_t, Eigen::Vector3d>& positions_enu_m,
                          const std::map<std::int64_t, imu_lab::io::TruthRecord>& truth,
                          const imu_lab::nav::LocalEnuFrame& world) {
  RunError error;
  for (const auto& [stamp_ns, position] : positions_enu_m) {
    const auto found = truth.find(stamp_ns);
    if (found == truth.end()) continue;
    const auto& t = found->second;
    const double horizontal_m = (position - world.enu_m(t.latitude_rad, t.longitude_rad, t.height_m)).head<2>().norm();
    error.max_horizontal_m = std::max(error.max_horizontal_m, horizontal_m);
    error.final_horizontal_m = horizontal_m;
    ++error.compared;
  }
  return error;
}

TEST(FullChain, CorrectedNavigationIsTenTimesBetterAndItsNoiseIsTheProfiles) {
  char pattern[] = "/tmp/imu_lab_full_chain_XXXXXX";
  const std::string directory = ::mkdtemp(pattern);
  const std::string profile = private_string("profile");
  const std::string thermal_bag = directory + "/thermal.bag", calibration_bag = directory + "/calibration.bag",
                    navigation_bag = directory + "/navigation.bag";
  const std::string thermal_model = directory + "/thermal.yaml", calibration = directory + "/calibration.yaml";
  const std::string log = " >> " + directory + "/tools.log 2>&1";
  std::printf("full_chain_check: working in %s\n", directory.c_str());

  // 1, 2: the sensor's own tests, emulated, and the models fitted from them.
  run_or_fail("rosrun imu_lab emulate --profile " + profile + " " + private_string("thermal_emulate_arguments") +
              " --out " + thermal_bag + log);
  run_or_fail("rosrun imu_lab emulate --profile " + profile + " " + private_string("calibration_emulate_arguments") +
              " --out " + calibration_bag + log);
  run_or_fail("rosrun imu_lab emulate --profile " + profile + " " + private_string("navigation_emulate_arguments") +
              " --out " + navigation_bag + log);
  run_or_fail("rosrun imu_lab fit_thermal " + thermal_bag + " " + private_string("fit_thermal_arguments") + " --out " +
              thermal_model + log);
  run_or_fail("rosrun imu_lab fit_calibration " + calibration_bag + " " + private_string("fit_calibration_arguments") +
              " --out " + calibration + log);
  // replace_thermal_model, replace_calibration: files the chain uses instead of the fitted ones,
  // to check that the test fails (full_chain.test's arguments of the same names).
  const auto replaced = [](const std::string& name, const std::string& fitted) {
    const std::string replacement = ros::param::param<std::string>("~" + name, "");
    return replacement.empty() ? fitted : replacement;
  };
  const std::string used_thermal_model = replaced("replace_thermal_model", thermal_model);
  const std::string used_calibration = replaced("replace_calibration", calibration);

  std::vector<imu_lab::io::ImuRecord> raw;
  imu_lab::ros_io::for_each_imu(navigation_bag, "/imu/raw", [&](const imu_lab::io::ImuRecord& r) { raw.push_back(r); });
  std::map<std::int64_t, imu_lab::io::TruthRecord> truth;
  imu_lab::ros_io::for_each_truth(navigation_bag, "/imu/truth",
                                  [&](const imu_lab::io::TruthRecord& t) { truth[t.stamp_ns] = t; });
  ASSERT_GT(raw.size(), 1000u);
  ASSERT_EQ(truth.size(), raw.size());

  // 3: the chain, from the launch file.
  ros::NodeHandle node;
  std::vector<CorrectedSample> corrected;
  std::map<std::int64_t, Eigen::Vector3d> chain_positions_enu_m;
  std::size_t allan_messages = 0;
  auto corrected_subscriber =
      node.subscribe<sensor_msgs::Imu>("/imu/corrected", 100000, [&](const sensor_msgs::Imu::ConstPtr& m) {
        const auto record = imu_lab::ros_io::to_imu_record(*m);
        corrected.push_back({record.stamp_ns, record.angular_rate_rad_s, record.specific_force_m_s2});
      });
  auto odometry_subscriber =
      node.subscribe<nav_msgs::Odometry>("/nav/odometry", 100000, [&](const nav_msgs::Odometry::ConstPtr& m) {
        const auto& p = m->pose.pose.position;
        chain_positions_enu_m[static_cast<std::int64_t>(m->header.stamp.toNSec())] = Eigen::Vector3d(p.x, p.y, p.z);
      });
  auto allan_subscriber = node.subscribe<imu_lab::AllanDeviation>(
      "/allan/gyro", 100, [&](const imu_lab::AllanDeviation::ConstPtr&) { ++allan_messages; });

  const std::string site = private_string("site_arguments");
  RunningLaunch launch;
  launch.pid = start_launch("roslaunch imu_lab full_chain.launch rviz:=false bag:=" + navigation_bag +
                            " thermal_model:=" + used_thermal_model + " calibration:=" + used_calibration + " " + site +
                            " " + private_string("launch_arguments") + " allan_report_dir:=" + directory +
                            "/allan_report play_args:='--pause --keep-alive' > " + directory + "/launch.log 2>&1");
  ASSERT_GT(launch.pid, 0);

  // Start the playback once every stage has registered and the checker is connected: a sample
  // published before a downstream connection exists would be lost to it.
  const ros::WallTime connect_deadline = ros::WallTime::now() + ros::WallDuration(90.0);
  auto connected = [&] {
    return registrations("/imu/raw").second >= 2 && registrations("/imu/temperature").second >= 1 &&
           registrations("/imu/thermal").second >= 1 && registrations("/imu/corrected").second >= 2 &&
           corrected_subscriber.getNumPublishers() > 0 && odometry_subscriber.getNumPublishers() > 0 &&
           ros::service::exists("/player/pause_playback", false);
  };
  while (ros::ok() && ros::WallTime::now() < connect_deadline && !connected()) {
    ros::spinOnce();
    ros::WallDuration(0.2).sleep();
  }
  if (!connected()) {
    FAIL() << "the chain did not come up within 90 s; see " << directory << "/launch.log";
  }
  // The stages' own connections follow their registrations: wait until every link of the chain is
  // connected on its publisher's side (a pause of a fixed length was outlasted on a busy machine).
  using imu_lab::connection_check::sends;
  const std::string checker = ros::this_node::getName();
  const bool linked = imu_lab::connection_check::wait_until(
      [&] {
        return sends("/player", "/imu/raw", "/thermal_compensator") &&
               sends("/player", "/imu/temperature", "/thermal_compensator") &&
               sends("/player", "/imu/raw", "/allan_monitor") &&
               sends("/thermal_compensator", "/imu/thermal", "/calibration_corrector") &&
               sends("/calibration_corrector", "/imu/corrected", "/strapdown_navigator") &&
               sends("/calibration_corrector", "/imu/corrected", checker) &&
               sends("/strapdown_navigator", "/nav/odometry", checker);
      },
      90.0);
  ASSERT_TRUE(linked) << "the chain's stages did not connect to each other within 90 s; see " << directory
                      << "/launch.log";
  std_srvs::SetBool resume;
  resume.request.data = false;
  ASSERT_TRUE(ros::service::call("/player/pause_playback", resume)) << "could not start the playback";

  const std::int64_t last_stamp_ns = raw.back().stamp_ns;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(private_double("playback_timeout_s"));
  while (ros::ok() && ros::WallTime::now() < deadline &&
         (corrected.size() < raw.size() || chain_positions_enu_m.count(last_stamp_ns) == 0)) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
  }
  ros::spinOnce();
  launch.stop();
  ASSERT_EQ(corrected.size(), raw.size()) << "samples lost between the bag and /imu/corrected; see " << directory;
  ASSERT_EQ(chain_positions_enu_m.count(last_stamp_ns), 1u) << "no odometry for the last sample; see " << directory;
  EXPECT_GT(allan_messages, 0u) << "allan_monitor on /imu/raw published nothing";

  // 4: the raw run through the same navigation, and both against the truth.
  const std::string raw_trajectory = directory + "/raw_trajectory.csv";
  run_or_fail("rosrun imu_lab navigate " + navigation_bag + " --topic /imu/raw " +
              private_string("navigate_arguments") + " --out " + raw_trajectory + log);
  std::map<std::int64_t, Eigen::Vector3d> raw_positions_enu_m;
  for (const auto& solution : imu_lab::pipeline::read_trajectory_csv(raw_trajectory)) {
    if (chain_positions_enu_m.count(solution.stamp_ns))
      raw_positions_enu_m[solution.stamp_ns] = solution.position_enu_m;
  }
  const imu_lab::nav::LocalEnuFrame world(imu_lab::nav::EarthModelConfig{}, private_double("latitude_deg") * kDegToRad,
                                          private_double("longitude_deg") * kDegToRad, private_double("height_m"));
  const RunError chain_error = horizontal_error(chain_positions_enu_m, truth, world);
  const RunError raw_error = horizontal_error(raw_positions_enu_m, truth, world);
  ASSERT_EQ(chain_error.compared, raw_error.compared);
  ASSERT_GT(chain_error.compared, 1000u);
  const double improvement = raw_error.max_horizontal_m / chain_error.max_horizontal_m;
  std::printf(
      "full_chain_check: largest horizontal error over %zu solutions: raw %.1f m, corrected chain %.2f m "
      "(%.1fx); at the end: %.1f m, %.2f m\n",
      chain_error.compared, raw_error.max_horizontal_m, chain_error.max_horizontal_m, improvement,
      raw_error.final_horizontal_m, chain_error.final_horizontal_m);
  EXPECT_GE(improvement, 10.0) << "raw " << raw_error.max_horizontal_m << " m, corrected "
                               << chain_error.max_horizontal_m << " m";

  // 5: the corrected stream's noise over the initial rest against the profile's. The correction
  // maps the raw noise n to K^-1 n (K the fitted scale/misalignment matrix), so each corrected
  // axis has the K^-1-weighted sum of the axes' AVARs (independent axes); the thermal scale
  // correction changes it by < 0.2 %, far inside the bounds.
  const auto sensor = imu_lab::emulator::load_sensor_profile(profile);
  const auto fitted = imu_lab::calib::load_calibration(calibration);
  const double rest_s = private_double("initial_rest_s");
  std::array<std::vector<double>, 6> channels;
  for (const auto& sample : corrected) {
    if (static_cast<double>(sample.stamp_ns - raw.front().stamp_ns) * 1e-9 >= rest_s) break;
    for (int axis = 0; axis < 3; ++axis) {
      channels[axis].push_back(sample.angular_rate_rad_s[axis]);
      channels[3 + axis].push_back(sample.specific_force_m_s2[axis]);
    }
  }
  const double tau0_s = static_cast<double>(raw[1].stamp_ns - raw[0].stamp_ns) * 1e-9;
  int largest_factor = 1;
  while (largest_factor * 2 * 10 <= static_cast<int>(channels[0].size())) largest_factor *= 2;  // >= ~10 clusters
  const double family_confidence_per_channel = 1.0 - (1.0 - 0.997) / 6.0;
  for (int c = 0; c < 6; ++c) {
    const bool gyro = c < 3;
    const auto& triad = gyro ? sensor.gyro : sensor.accelerometer;
    const Eigen::Matrix3d k_inverse = (gyro ? fitted.gyro : fitted.accelerometer).scale_misalignment.inverse();
    const int axis = c % 3;
    const auto expected_avar = [&](double tau_s) {
      double avar = 0.0;
      for (int j = 0; j < 3; ++j) {
        avar +=
            k_inverse(axis, j) * k_inverse(axis, j) * imu_lab::emulator::analytic_axis_avar(triad, j, tau_s, tau0_s);
      }
      return avar;
    };
    const auto check =
        imu_lab::test::check_avar(channels[c], tau0_s, expected_avar, 1, largest_factor, family_confidence_per_channel);
    EXPECT_TRUE(check.passed()) << "channel " << c << " (" << channels[c].size() << " samples)\n" << check.table;
    std::printf("full_chain_check: channel %d: %d points, worst ratio %.3f (%.2f sigma)\n", c, check.point_count,
                check.worst_ratio, check.worst_normalised_deviation);
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "full_chain_check");
  ros::NodeHandle node;
  return RUN_ALL_TESTS();
}
