// common/stamps.h rounds seconds as ros::Time and ros::Duration do, so an emulated sample's
// integer stamp is the one its message carries, and a stamp's seconds are ros::Time::toSec's.
#include <gtest/gtest.h>
#include <ros/time.h>

#include <cstdint>
#include <random>

#include "imu_lab/common/stamps.h"

namespace {

TEST(StampsRosTime, SecondsRoundAsRosTimeAndDurationDo) {
  std::mt19937_64 generator(20261202);
  // Stamps up to ROS time's end (2106), and durations: whole, fractional and near-half values.
  std::uniform_real_distribution<double> stamp_s(0.0, 4.29e9), duration_s(0.0, 1e5);
  std::uniform_int_distribution<std::int64_t> whole_s(0, 4000000000);
  for (int k = 0; k < 100000; ++k) {
    const double t = stamp_s(generator);
    ASSERT_EQ(imu_lab::stamp_ns_from_seconds(t), static_cast<std::int64_t>(ros::Time(t).toNSec())) << t;
    const double d = duration_s(generator);
    ASSERT_EQ(imu_lab::stamp_ns_from_seconds(d), ros::Duration(d).toNSec()) << d;
    const double near_half = static_cast<double>(whole_s(generator)) + (k % 1000) * 1e-9 + 0.5e-9;
    ASSERT_EQ(imu_lab::stamp_ns_from_seconds(near_half), static_cast<std::int64_t>(ros::Time(near_half).toNSec()))
        << near_half;
  }
}

TEST(StampsRosTime, SecondsOfAStampAreRosTimeToSec) {
  std::mt19937_64 generator(7);
  std::uniform_int_distribution<std::uint64_t> stamp_ns(0, 4290000000ULL * 1000000000ULL);
  for (int k = 0; k < 100000; ++k) {
    const std::uint64_t ns = stamp_ns(generator);
    ros::Time time;
    time.fromNSec(ns);
    ASSERT_EQ(imu_lab::seconds_from_stamp_ns(static_cast<std::int64_t>(ns)), time.toSec()) << ns;
  }
}

}  // namespace
