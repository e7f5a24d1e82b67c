// The correct tool, run as a user runs it: its output equals what the live chain publishes for the
// same bag (thermal_compensator's core, ThermalCompensator fed in bag order as rosbag play feeds
// the node, then calibration_corrector's corrected_message) bit for bit; the other topics are
// copied unchanged; and the inputs only `correct` has (a thermal model without temperature, an
// unreadable model, no model) are refused with a message and no output. The bag-level refusals
// shared with the other tools are in test_tools_bad_input.cpp.
#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <deque>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/ros_io/node/calibration_corrector_node.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/thermal/thermal_compensator.h"
#include "imu_lab/thermal/thermal_model_yaml.h"
#include "ros_test_support.h"

namespace {

using namespace imu_lab::test_support;  // NOLINT: the scratch and tool helpers

const std::string kThermalModel = std::string(IMU_LAB_TEST_DATA_DIR) + "/thermal/model_uncompensated_mems_gyro.yaml";
const std::string kCalibration = std::string(IMU_LAB_TEST_DATA_DIR) + "/calibration_example.yaml";
constexpr double kMaxTemperatureAge_s = 1.0;  // the node's and the tool's default
constexpr std::uint64_t kStart_ns = 1'700'000'000'000'000'000ULL;

// 200 s at 100 Hz with a 10 Hz thermosensor ramping 66 -> 72 degC at 0.03 degC/s: inside the
// model's range (to 68.66 degC), then above it (clamped); readings stop for 5 s at 120 s (about
// 300 samples stale); the IMU is recorded 2 ms after its stamp; covariances are set so their
// carriage through K^-1 C K^-T is compared too; an unrelated topic must be copied.
struct ChainBag {
  std::string path;
  explicit ChainBag(const std::string& directory, bool with_temperature = true, double temperature_offset_s = 0.0)
      : path(directory + "/in.bag") {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    std::mt19937_64 generator(7);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
      const double t_s = i * 0.01;
      ros::Time stamp;
      stamp.fromNSec(kStart_ns + static_cast<std::uint64_t>(i) * 10'000'000ULL);
      sensor_msgs::Imu imu;
      imu.header.stamp = stamp;
      imu.header.seq = static_cast<std::uint32_t>(i);
      imu.header.frame_id = "imu_link";
      imu.orientation_covariance[0] = -1.0;
      imu.angular_velocity.x = 1e-3 * normal(generator);
      imu.angular_velocity.y = 2e-4 + 1e-3 * normal(generator);
      imu.angular_velocity.z = 1e-3 * normal(generator);
      imu.linear_acceleration.x = 0.05 + 1e-2 * normal(generator);
      imu.linear_acceleration.y = 1e-2 * normal(generator);
      imu.linear_acceleration.z = 9.81 + 1e-2 * normal(generator);
      for (int k = 0; k < 9; k += 4) imu.angular_velocity_covariance[k] = 1e-6 * (1 + k);
      imu.angular_velocity_covariance[1] = imu.angular_velocity_covariance[3] = 2e-7;
      for (int k = 0; k < 9; k += 4) imu.linear_acceleration_covariance[k] = 1e-4 * (1 + k);
      bag.write("/imu/raw", stamp + ros::Duration(0.002), imu);
      const bool in_gap = t_s > 120.0 && t_s < 125.0;
      if (with_temperature && i % 10 == 0 && !in_gap) {
        sensor_msgs::Temperature temperature;
        temperature.header.stamp = stamp + ros::Duration(temperature_offset_s);
        temperature.temperature = 66.0 + 0.03 * t_s + 0.01 * normal(generator);
        bag.write("/imu/temperature", temperature.header.stamp, temperature);
      }
      if (i % 100 == 0) {
        sensor_msgs::Temperature board;  // an unrelated topic, copied as it is
        board.header.stamp = stamp;
        board.temperature = 30.0;
        bag.write("/board/temperature", stamp, board);
      }
    }
  }
};

// What the live chain publishes: thermal_compensator (ThermalCompensatorNode::on_imu,
// on_temperature, publish) then calibration_corrector (corrected_message), messages in bag order.
struct LiveChain {
  std::vector<sensor_msgs::Imu> published;
  std::size_t clamped = 0, stale = 0;
};

LiveChain run_live_chain(const std::string& bag_path, bool thermal, bool calibration) {
  LiveChain chain;
  imu_lab::thermal::ThermalCompensator compensator(imu_lab::thermal::load_thermal_model(kThermalModel),
                                                   kMaxTemperatureAge_s);
  const imu_lab::calib::ImuCalibration corrector = imu_lab::calib::load_calibration(kCalibration);
  std::deque<sensor_msgs::Imu> waiting;
  const auto calibrate = [&](const sensor_msgs::Imu& message) {
    chain.published.push_back(calibration ? imu_lab::ros_io::corrected_message(message, corrector) : message);
  };
  const auto publish = [&](const std::vector<imu_lab::thermal::CompensatedSample>& ready) {
    for (const auto& sample : ready) {
      sensor_msgs::Imu output = waiting.front();
      waiting.pop_front();
      if (sample.status == imu_lab::thermal::CompensatedSample::Status::kStale) {
        ++chain.stale;
        continue;
      }
      if (sample.status == imu_lab::thermal::CompensatedSample::Status::kClamped) ++chain.clamped;
      output.angular_velocity.x = sample.corrected.angular_rate_rad_s.x();
      output.angular_velocity.y = sample.corrected.angular_rate_rad_s.y();
      output.angular_velocity.z = sample.corrected.angular_rate_rad_s.z();
      output.linear_acceleration.x = sample.corrected.specific_force_m_s2.x();
      output.linear_acceleration.y = sample.corrected.specific_force_m_s2.y();
      output.linear_acceleration.z = sample.corrected.specific_force_m_s2.z();
      calibrate(output);
    }
  };
  rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
  for (const rosbag::MessageInstance& instance : rosbag::View(bag)) {
    std::vector<imu_lab::thermal::CompensatedSample> ready;
    if (instance.getTopic() == "/imu/raw") {
      const auto message = instance.instantiate<sensor_msgs::Imu>();
      if (!thermal) {
        calibrate(*message);
        continue;
      }
      const auto record = imu_lab::ros_io::to_imu_record(*message);
      if (compensator.add_imu(record, &ready)) {
        waiting.push_back(*message);
      }
    } else if (thermal && instance.getTopic() == "/imu/temperature") {
      const auto message = instance.instantiate<sensor_msgs::Temperature>();
      compensator.add_temperature(static_cast<std::int64_t>(message->header.stamp.toNSec()), message->temperature,
                                  &ready);
    }
    publish(ready);
  }
  // The end of the bag: the tool decides the last waiting samples with what has arrived (a live
  // node would on the next reading).
  std::vector<imu_lab::thermal::CompensatedSample> ready;
  if (thermal) compensator.flush(&ready);
  publish(ready);
  return chain;
}

template <class Message>
std::vector<Message> read_topic(const std::string& bag_path, const std::string& topic) {
  std::vector<Message> messages;
  rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
  for (const rosbag::MessageInstance& instance : rosbag::View(bag, rosbag::TopicQuery(topic))) {
    messages.push_back(*instance.instantiate<Message>());
  }
  return messages;
}

void expect_identical(const sensor_msgs::Imu& expected, const sensor_msgs::Imu& actual, std::size_t index) {
  ASSERT_EQ(expected.header.stamp, actual.header.stamp) << "message " << index;
  EXPECT_EQ(expected.header.seq, actual.header.seq) << index;
  EXPECT_EQ(expected.header.frame_id, actual.header.frame_id) << index;
  // Bit for bit: the same functions on the same inputs.
  EXPECT_EQ(expected.angular_velocity.x, actual.angular_velocity.x) << index;
  EXPECT_EQ(expected.angular_velocity.y, actual.angular_velocity.y) << index;
  EXPECT_EQ(expected.angular_velocity.z, actual.angular_velocity.z) << index;
  EXPECT_EQ(expected.linear_acceleration.x, actual.linear_acceleration.x) << index;
  EXPECT_EQ(expected.linear_acceleration.y, actual.linear_acceleration.y) << index;
  EXPECT_EQ(expected.linear_acceleration.z, actual.linear_acceleration.z) << index;
  EXPECT_EQ(expected.orientation, actual.orientation) << index;
  EXPECT_EQ(expected.orientation_covariance, actual.orientation_covariance) << index;
  EXPECT_EQ(expected.angular_velocity_covariance, actual.angular_velocity_covariance) << index;
  EXPECT_EQ(expected.linear_acceleration_covariance, actual.linear_acceleration_covariance) << index;
}

void expect_equal_to_live_chain(const std::string& bag, const std::string& out, const std::string& out_topic,
                                bool thermal, bool calibration) {
  const LiveChain live = run_live_chain(bag, thermal, calibration);
  const std::vector<sensor_msgs::Imu> written = read_topic<sensor_msgs::Imu>(out, out_topic);
  ASSERT_EQ(written.size(), live.published.size());
  for (std::size_t i = 0; i < written.size(); ++i) expect_identical(live.published[i], written[i], i);
}

TEST(CorrectTool, ThermalThenCalibrationEqualsTheLiveChainBitForBit) {
  const std::string directory = scratch_directory();
  const ChainBag bag(directory);
  const std::string out = directory + "/out.bag";
  const CommandResult result = run_tool(
      "correct", bag.path + " --thermal-model " + kThermalModel + " --calibration " + kCalibration + " --out " + out);
  ASSERT_EQ(result.exit_code, 0) << result.output;

  const LiveChain live = run_live_chain(bag.path, true, true);
  // The bag exercises all three outcomes: corrected, clamped at the range's edge, stale.
  EXPECT_GT(live.clamped, 5000u);
  EXPECT_LT(live.clamped, 15000u);
  EXPECT_GT(live.stale, 250u);
  EXPECT_LT(live.stale, 350u);
  expect_equal_to_live_chain(bag.path, out, "/imu/raw", true, true);
  const std::string counts = std::to_string(live.published.size()) + " of 20000 IMU messages on /imu/raw corrected";
  EXPECT_NE(result.output.find(counts), std::string::npos) << result.output;
  EXPECT_NE(result.output.find(std::to_string(live.clamped) + " samples outside the thermal model's validity range"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find(std::to_string(live.stale) + " samples skipped"), std::string::npos) << result.output;

  // The other topics, byte for byte in content, in the same order.
  for (const char* topic : {"/imu/temperature", "/board/temperature"}) {
    const auto in = read_topic<sensor_msgs::Temperature>(bag.path, topic);
    const auto copied = read_topic<sensor_msgs::Temperature>(out, topic);
    ASSERT_EQ(in.size(), copied.size()) << topic;
    for (std::size_t i = 0; i < in.size(); ++i) {
      EXPECT_EQ(in[i].header.stamp, copied[i].header.stamp) << topic << " " << i;
      EXPECT_EQ(in[i].temperature, copied[i].temperature) << topic << " " << i;
    }
  }
  EXPECT_EQ(list_directory(directory), (std::vector<std::string>{"in.bag", "out.bag"}));
}

TEST(CorrectTool, EachStageAloneEqualsItsNode) {
  const std::string directory = scratch_directory();
  const ChainBag bag(directory);
  const std::string calibrated = directory + "/calibrated.bag";
  const CommandResult calibration_only =
      run_tool("correct", bag.path + " --calibration " + kCalibration + " --out " + calibrated);
  ASSERT_EQ(calibration_only.exit_code, 0) << calibration_only.output;
  expect_equal_to_live_chain(bag.path, calibrated, "/imu/raw", false, true);

  // Thermal only, onto another topic: the raw topic stays beside it.
  const std::string compensated = directory + "/compensated.bag";
  const CommandResult thermal_only = run_tool(
      "correct", bag.path + " --thermal-model " + kThermalModel + " --out-topic /imu/thermal --out " + compensated);
  ASSERT_EQ(thermal_only.exit_code, 0) << thermal_only.output;
  expect_equal_to_live_chain(bag.path, compensated, "/imu/thermal", true, false);
  EXPECT_EQ(read_topic<sensor_msgs::Imu>(compensated, "/imu/raw").size(), 20000u);
}

// Exit `exit_code`, every word in the output, nothing written.
void expect_refused(const std::string& arguments, int exit_code, const std::vector<std::string>& words,
                    const std::string& out_directory) {
  const CommandResult result = run_tool("correct", arguments);
  EXPECT_EQ(result.exit_code, exit_code) << arguments << "\n" << result.output;
  for (const std::string& word : words) {
    EXPECT_NE(result.output.find(word), std::string::npos) << "no '" << word << "' in\n" << result.output;
  }
  EXPECT_EQ(list_directory(out_directory), std::vector<std::string>{}) << "partial output after " << arguments;
}

TEST(CorrectToolBadInput, AThermalModelWithoutTemperatureIsRefusedNamingTheTopic) {
  const std::string inputs = scratch_directory(), outputs = scratch_directory();
  const ChainBag bag(inputs, false);
  const std::string out = " --out " + outputs + "/out.bag";
  expect_refused(bag.path + " --thermal-model " + kThermalModel + out, 1,
                 {bag.path, "/imu/temperature", "--temperature-topic", "--calibration only"}, outputs);
  expect_refused(bag.path + " --thermal-model " + kThermalModel + " --temperature-topic /board/temp" + out, 1,
                 {bag.path, "/board/temp", "/board/temperature"}, outputs);
  // Calibration alone needs no temperature.
  EXPECT_EQ(run_tool("correct", bag.path + " --calibration " + kCalibration + out).exit_code, 0);
}

TEST(CorrectToolBadInput, TemperatureNeverNearTheSamplesIsRefused) {
  const std::string inputs = scratch_directory(), outputs = scratch_directory();
  const ChainBag bag(inputs, true, 1000.0);  // every reading 1000 s after the IMU
  expect_refused(bag.path + " --thermal-model " + kThermalModel + " --out " + outputs + "/out.bag", 1,
                 {bag.path, "none of the 20000 samples", "no temperature within"}, outputs);
}

TEST(CorrectToolBadInput, UnreadableModelsAreConfigurationErrorsNamingTheFile) {
  const std::string inputs = scratch_directory(), outputs = scratch_directory();
  const ChainBag bag(inputs);
  const std::string out = " --out " + outputs + "/out.bag";
  const std::string missing = inputs + "/missing.yaml";
  expect_refused(bag.path + " --thermal-model " + missing + out, 2, {missing, "cannot open"}, outputs);
  expect_refused(bag.path + " --calibration " + missing + out, 2, {missing, "cannot open"}, outputs);
  const std::string garbage = inputs + "/garbage.yaml";
  std::ofstream(garbage) << "format: imu_lab_thermal_model\nversion: 1\n";
  expect_refused(bag.path + " --thermal-model " + garbage + out, 2, {garbage}, outputs);
  expect_refused(bag.path + " --calibration " + garbage + out, 2, {garbage, "format"}, outputs);
  expect_refused(bag.path + out, 2, {"--thermal-model", "--calibration"}, outputs);
}

TEST(CorrectToolBadInput, NanTemperatureIsRefused) {
  const std::string inputs = scratch_directory(), outputs = scratch_directory();
  const std::string path = inputs + "/nan.bag";
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    for (int i = 0; i < 1000; ++i) {
      ros::Time stamp;
      stamp.fromNSec(kStart_ns + static_cast<std::uint64_t>(i) * 10'000'000ULL);
      sensor_msgs::Imu imu;
      imu.header.stamp = stamp;
      imu.linear_acceleration.z = 9.81;
      bag.write("/imu/raw", stamp, imu);
      sensor_msgs::Temperature temperature;
      temperature.header.stamp = stamp;
      temperature.temperature = i == 500 ? std::numeric_limits<double>::quiet_NaN() : 25.0;
      bag.write("/imu/temperature", stamp, temperature);
    }
  }
  expect_refused(path + " --thermal-model " + kThermalModel + " --out " + outputs + "/out.bag", 1,
                 {path, "1 of 1000 readings on /imu/temperature"}, outputs);
}

TEST(CorrectToolBadInput, AnOutputTopicThatExistsIsRefused) {
  const std::string inputs = scratch_directory(), outputs = scratch_directory();
  const ChainBag bag(inputs);
  expect_refused(
      bag.path + " --calibration " + kCalibration + " --out-topic /board/temperature --out " + outputs + "/out.bag", 1,
      {bag.path, "/board/temperature", "already"}, outputs);
}

}  // namespace
