#include "imu_lab/ros_io/bag/imu_bag_reader.h"

#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/MagneticField.h>

#include <fstream>

#include "imu_lab/common/config_error.h"
#include "ros_test_support.h"

#ifndef IMU_LAB_REFERENCE_DIR
#define IMU_LAB_REFERENCE_DIR "../shared/reference"
#endif

namespace {

using imu_lab::InputError;
using imu_lab::ros_io::choose_imu_topic;
using imu_lab::ros_io::for_each_imu;
using imu_lab::test_support::scratch_directory;

std::string expect_input_error(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

std::string write_bag(const std::string& path, const std::vector<std::string>& imu_topics, int count) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  for (int i = 0; i < count; ++i) {
    sensor_msgs::Imu imu;
    imu.header.stamp.fromSec(100.0 + 0.01 * i);
    imu.angular_velocity.x = i;
    for (const auto& topic : imu_topics) bag.write(topic, imu.header.stamp, imu);
    sensor_msgs::MagneticField field;
    field.header = imu.header;
    bag.write("/imu/mag", imu.header.stamp, field);
  }
  return path;
}

TEST(ImuBagReader, ReadsTheRealCompressedBagsWithTheirUnevenStamps) {
  struct Expected {
    const char* file;
    std::size_t count;
  };
  for (const Expected& bag : {Expected{"phidgets_imu_upside_down.bag", 13964}, Expected{"sparkfun_razor.bag", 2144}}) {
    const std::string path = std::string(IMU_LAB_REFERENCE_DIR) + "/real_bags/" + bag.file;
    const std::string topic = choose_imu_topic(path, "");
    EXPECT_EQ(topic, "/imu/data_raw");
    std::int64_t previous_ns = 0;
    std::size_t unordered = 0;
    const std::size_t count = for_each_imu(path, topic, [&](const imu_lab::io::ImuRecord& record) {
      if (record.stamp_ns <= previous_ns) ++unordered;
      previous_ns = record.stamp_ns;
    });
    EXPECT_EQ(count, bag.count) << bag.file;
    EXPECT_LT(unordered, count / 100) << bag.file;
  }
}

TEST(ImuBagReader, WrongTopicNamesTheTopicsThatExist) {
  const std::string path = write_bag(scratch_directory() + "/one.bag", {"/imu/raw"}, 3);
  const std::string message = expect_input_error([&] { choose_imu_topic(path, "/imu/nothing"); });
  EXPECT_NE(message.find("/imu/nothing"), std::string::npos) << message;
  EXPECT_NE(message.find("/imu/raw"), std::string::npos) << message;
  const std::string wrong_type = expect_input_error([&] { choose_imu_topic(path, "/imu/mag"); });
  EXPECT_NE(wrong_type.find("sensor_msgs/MagneticField"), std::string::npos) << wrong_type;
}

TEST(ImuBagReader, SeveralImuTopicsAskForAChoice) {
  const std::string path = write_bag(scratch_directory() + "/two.bag", {"/imu/a", "/imu/b"}, 3);
  const std::string message = expect_input_error([&] { choose_imu_topic(path, ""); });
  EXPECT_NE(message.find("--topic"), std::string::npos) << message;
  EXPECT_EQ(choose_imu_topic(path, "/imu/b"), "/imu/b");
  EXPECT_EQ(for_each_imu(path, "/imu/b", [](const imu_lab::io::ImuRecord&) {}), 3u);
}

TEST(ImuBagReader, EmptyBagHasNoImuTopic) {
  const std::string path = scratch_directory() + "/empty.bag";
  { rosbag::Bag bag(path, rosbag::bagmode::Write); }
  const std::string message = expect_input_error([&] { choose_imu_topic(path, ""); });
  EXPECT_NE(message.find("no sensor_msgs/Imu topic"), std::string::npos) << message;
}

TEST(ImuBagReader, TruncatedAndGarbageBagsAreRefusedClearly) {
  const std::string directory = scratch_directory();
  const std::string whole = write_bag(directory + "/whole.bag", {"/imu/raw"}, 2000);
  const std::string bytes = imu_lab::test_support::read_file(whole);
  {
    std::ofstream(directory + "/truncated.bag", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    std::ofstream(directory + "/garbage.bag", std::ios::binary) << "this is not a bag\n";
  }
  for (const char* name : {"/truncated.bag", "/garbage.bag", "/missing.bag"}) {
    const std::string message = expect_input_error([&] { choose_imu_topic(directory + name, ""); });
    EXPECT_NE(message.find(directory + name), std::string::npos) << message;
  }
}

}  // namespace
