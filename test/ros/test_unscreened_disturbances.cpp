// bag_summary and spectrum keep every sample; where allan's screens would leave a knock out, they
// say so (issue 46: on the knocked ADIS16405 bag_summary's OADEV at 100 s was 5.2e-3 m/s^2 in
// accelerometer y against allan's 3.0e-3, without a word). A clean record gets no note.
#include <gtest/gtest.h>

#include "allan_test_support.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::add_knock;
using imu_lab::test_support::contains;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;
using imu_lab::test_support::white_noise_samples;
using imu_lab::test_support::write_imu_bag;

// 60 s of white noise at 200 Hz, knocked at 30 s (add_knock) or clean.
std::string white_bag(bool knocked) {
  auto samples = white_noise_samples(12000, 5'000'000, 3);
  if (knocked) add_knock(samples, 6000);
  const std::string bag = scratch_directory() + (knocked ? "/knocked.bag" : "/clean.bag");
  write_imu_bag(bag, samples);
  return bag;
}

const std::string kNote = "note: allan's screens find 1 knock(s) or spike(s) (first at 30.0 s from the start";

TEST(UnscreenedDisturbances, BagSummarySaysWhatAllanWouldLeaveOut) {
  const auto knocked = run_tool("bag_summary", white_bag(true));
  ASSERT_EQ(knocked.exit_code, 0) << knocked.output;
  EXPECT_TRUE(contains(knocked.output, "bag_summary: " + kNote)) << knocked.output;
  EXPECT_TRUE(contains(knocked.output, "scales in accel_z")) << knocked.output;
  EXPECT_TRUE(contains(knocked.output, "--no-impulse-screen --no-level-shift-screen keeps them")) << knocked.output;
  const auto clean = run_tool("bag_summary", white_bag(false));
  ASSERT_EQ(clean.exit_code, 0) << clean.output;
  EXPECT_FALSE(contains(clean.output, "allan's screens")) << clean.output;
}

TEST(UnscreenedDisturbances, SpectrumSaysWhatAllanWouldLeaveOut) {
  const auto knocked = run_tool("spectrum", white_bag(true) + " --no-plot -o " + scratch_directory() + "/spectrum");
  ASSERT_EQ(knocked.exit_code, 0) << knocked.output;
  EXPECT_TRUE(contains(knocked.output, "spectrum: " + kNote)) << knocked.output;
  const auto clean = run_tool("spectrum", white_bag(false) + " --no-plot -o " + scratch_directory() + "/spectrum");
  ASSERT_EQ(clean.exit_code, 0) << clean.output;
  EXPECT_FALSE(contains(clean.output, "allan's screens")) << clean.output;
}

}  // namespace
