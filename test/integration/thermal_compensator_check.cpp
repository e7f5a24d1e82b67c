// rostest checker for thermal_compensator: emulates a thermal bag, computes the core library's
// correction of every sample (thermal::ThermalCompensator fed the bag in stamp order), then plays
// the bag with `rosbag play --clock` into the node and checks that each message on /imu/thermal
// equals it at the same stamp and that every sample came through. Counts and generous time-outs
// only, never wall-clock rates.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <stdlib.h>

#include <cstdio>
#include <map>
#include <string>

#include "connection_support.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/thermal/thermal_compensator.h"
#include "imu_lab/thermal/thermal_model_yaml.h"

namespace {

std::string private_string(const std::string& name) {
  std::string value;
  ros::param::get("~" + name, value);
  return value;
}

void run_or_fail(const std::string& command) { ASSERT_EQ(std::system(command.c_str()), 0) << "failed: " << command; }

// The core library's answer: all readings of the bag, fed in header-stamp order.
std::map<std::int64_t, imu_lab::thermal::CompensatedSample> reference_of(const std::string& bag, double max_age_s) {
  imu_lab::thermal::ThermalCompensator compensator(imu_lab::thermal::load_thermal_model(private_string("model_file")),
                                                   max_age_s);
  std::vector<imu_lab::io::TemperatureRecord> temperatures;
  imu_lab::ros_io::for_each_temperature(bag, "/imu/temperature", [&](const auto& r) { temperatures.push_back(r); });
  std::vector<imu_lab::thermal::CompensatedSample> ready;
  std::vector<std::int64_t> stamps_ns;  // exact, in the order the samples come out
  std::size_t next_temperature = 0;
  imu_lab::ros_io::for_each_imu(bag, "/imu/raw", [&](const imu_lab::io::ImuRecord& r) {
    while (next_temperature < temperatures.size() && temperatures[next_temperature].stamp_ns <= r.stamp_ns) {
      compensator.add_temperature(temperatures[next_temperature].stamp_ns, temperatures[next_temperature].temperature_c,
                                  &ready);
      ++next_temperature;
    }
    if (compensator.add_imu(r, &ready)) stamps_ns.push_back(r.stamp_ns);
  });
  compensator.flush(&ready);
  std::map<std::int64_t, imu_lab::thermal::CompensatedSample> by_stamp;
  for (std::size_t i = 0; i < ready.size(); ++i) by_stamp[stamps_ns.at(i)] = ready[i];
  return by_stamp;
}

TEST(ThermalCompensatorNode, PublishesTheCoreLibrarysCorrectionOfEverySample) {
  char pattern[] = "/tmp/imu_lab_thermal_check_XXXXXX";
  const std::string directory = ::mkdtemp(pattern);
  const std::string bag = directory + "/thermal.bag";
  run_or_fail("rosrun imu_lab emulate " + private_string("emulate_arguments") + " --out " + bag + " > " + directory +
              "/emulate.log 2>&1");
  double max_age_s = 1.0;
  ros::param::get("~max_temperature_age_s", max_age_s);
  const auto reference = reference_of(bag, max_age_s);
  ASSERT_GT(reference.size(), 1000u);
  std::size_t with_rate = 0;
  for (const auto& entry : reference) {
    ASSERT_NE(entry.second.status, imu_lab::thermal::CompensatedSample::Status::kStale);
    if (std::abs(entry.second.input.rate_c_s) > 1e-3) ++with_rate;
  }
  EXPECT_GT(with_rate, 100u) << "the replay should reach the ramp, where the rate term acts";

  ros::NodeHandle node;
  std::map<std::int64_t, sensor_msgs::Imu> received;
  auto subscriber = node.subscribe<sensor_msgs::Imu>(
      "imu/thermal", 100000, [&](const sensor_msgs::Imu::ConstPtr& m) { received[m->header.stamp.toNSec()] = *m; });
  // The node's subscriptions make --wait-for-subscribers start the playback.
  // The last sample waits for a temperature after it or for 1 s of newer IMU data: there is none,
  // so the node holds it back; every other sample must arrive.
  ASSERT_TRUE(imu_lab::connection_check::play_and_collect(
      bag, private_string("play_arguments"), directory + "/play.log", "/thermal_compensator", "/imu/thermal",
      [&] { return received.size() + 1 >= reference.size(); }, 240.0));
  ASSERT_GE(received.size() + 1, reference.size()) << "the node did not publish every sample in time";

  double worst_rate_rad_s = 0.0, worst_force_m_s2 = 0.0;
  std::size_t compared = 0;
  for (const auto& [stamp_ns, message] : received) {
    const auto expected = reference.find(stamp_ns);
    ASSERT_NE(expected, reference.end()) << "the node published a stamp the bag does not have: " << stamp_ns;
    const auto& c = expected->second.corrected;
    worst_rate_rad_s = std::max({worst_rate_rad_s, std::abs(message.angular_velocity.x - c.angular_rate_rad_s.x()),
                                 std::abs(message.angular_velocity.y - c.angular_rate_rad_s.y()),
                                 std::abs(message.angular_velocity.z - c.angular_rate_rad_s.z())});
    worst_force_m_s2 = std::max({worst_force_m_s2, std::abs(message.linear_acceleration.x - c.specific_force_m_s2.x()),
                                 std::abs(message.linear_acceleration.y - c.specific_force_m_s2.y()),
                                 std::abs(message.linear_acceleration.z - c.specific_force_m_s2.z())});
    EXPECT_EQ(message.header.frame_id, "imu_link");
    ++compared;
  }
  std::printf("[thermal_compensator_check] %zu of %zu samples vs the core library: worst %.3g rad/s, %.3g m/s^2\n",
              compared, reference.size(), worst_rate_rad_s, worst_force_m_s2);
  EXPECT_LT(worst_rate_rad_s, 1e-15);
  EXPECT_LT(worst_force_m_s2, 1e-12);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "thermal_compensator_check");
  return RUN_ALL_TESTS();
}
