// The demo's navigation-grade comparison, through the tools and scripts/navigation_budget.py as
// scripts/demo runs them (half an hour at rest instead of an hour, 10 Hz instead of 20): the raw
// and corrected navigation errors differ by what the first-order error model makes of the terms
// the calibration removes, the corrected error stays inside the bound of what it cannot remove,
// and another power-up's error minus this one's inside the bound of what the profile lets differ
// between power-ups. And the check can fail: a corrected run from another calibration is not
// explained by this calibration's terms.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "ros_test_support.h"

#ifndef IMU_LAB_CONFIG_DIR
#define IMU_LAB_CONFIG_DIR "config"
#endif

namespace {

using imu_lab::test_support::run_command;
using imu_lab::test_support::run_tool;

const std::string kBudgetScript = std::string(IMU_LAB_CONFIG_DIR) + "/../scripts/navigation_budget.py";

void run_or_fail(const std::string& tool, const std::string& arguments) {
  const auto run = run_tool(tool, arguments);
  ASSERT_EQ(run.exit_code, 0) << tool << " " << arguments << "\n" << run.output;
}

class NavigationBudget : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = new std::string(imu_lab::test_support::scratch_directory());
    const std::string& d = *directory_;
    ::mkdir((d + "/rlg").c_str(), 0755);
    run_or_fail("emulate",
                "--profile rlg_navigation --scenario multiposition_12_thesis --rate-hz 100 --seed 5 "
                "--no-truth --no-increments --out " +
                    d + "/calibration.bag");
    run_or_fail("fit_calibration",
                d + "/calibration.bag --schedule multiposition_12_thesis --out " + d + "/rlg/calibration.yaml");
    for (const char* seed : {"5", "6"}) {
      const std::string bag = d + "/rest_" + seed + ".bag";
      run_or_fail("emulate",
                  std::string("--profile rlg_navigation --scenario static_calibration_site --duration-s 1800 "
                              "--rate-hz 10 --no-increments --seed ") +
                      seed + " --out " + bag);
      run_or_fail("correct",
                  bag + " --calibration " + d + "/rlg/calibration.yaml --out " + d + "/corrected_" + seed + ".bag");
    }
    navigate(d + "/rest_5.bag", d + "/rlg/raw_trajectory.csv");
    navigate(d + "/corrected_5.bag", d + "/rlg/corrected_trajectory.csv");
    navigate(d + "/corrected_6.bag", d + "/rlg/new_turn_on_trajectory.csv");
  }
  static void navigate(const std::string& bag, const std::string& out) {
    run_or_fail("navigate", bag + " --no-align --every-s 10 --out " + out);
  }
  static std::string* directory_;
};
std::string* NavigationBudget::directory_ = nullptr;

TEST_F(NavigationBudget, RawMinusCorrectedIsWhatTheRemovedTermsGiveAndTheRestIsInsideTheBounds) {
  const auto budget =
      run_command("/usr/bin/python3 " + kBudgetScript + " " + *directory_ + "/rlg --profile rlg_navigation --check");
  std::printf("%s", budget.output.c_str());
  EXPECT_EQ(budget.exit_code, 0) << budget.output;
  EXPECT_NE(budget.output.find(": explained"), std::string::npos);
  const YAML::Node result = YAML::LoadFile(*directory_ + "/rlg/budget.yaml");
  // Not vacuous: the calibration changes the error by far more than the mismatch allowed.
  EXPECT_GT(result["removed_terms"]["measured_final_position_m"].as<double>(),
            20.0 * result["removed_terms"]["position_tolerance_m"].as<double>());
  EXPECT_TRUE(result["corrected"]["inside"].as<bool>());
  EXPECT_TRUE(result["power_up_difference"]["inside"].as<bool>());
}

TEST_F(NavigationBudget, ACorrectedRunFromAnotherCalibrationIsNotExplained) {
  const std::string wrong = *directory_ + "/wrong";
  ::mkdir(wrong.c_str(), 0755);
  // Another calibration: the accelerometer biases doubled (a few hundred micro-g more).
  YAML::Node calibration = YAML::LoadFile(*directory_ + "/rlg/calibration.yaml");
  for (std::size_t axis = 0; axis < 3; ++axis) {
    calibration["accelerometer"]["bias_m_s2"][axis] =
        2.0 * calibration["accelerometer"]["bias_m_s2"][axis].as<double>();
  }
  std::ofstream(wrong + "/other_calibration.yaml") << calibration;
  run_or_fail("correct", *directory_ + "/rest_5.bag --calibration " + wrong + "/other_calibration.yaml --out " + wrong +
                             "/corrected.bag");
  run_or_fail("navigate",
              wrong + "/corrected.bag --no-align --every-s 10 --out " + wrong + "/corrected_trajectory.csv");
  for (const char* file : {"calibration.yaml", "raw_trajectory.csv", "raw_trajectory_errors.csv"}) {
    ASSERT_EQ(run_command("cp " + *directory_ + "/rlg/" + file + " " + wrong + "/").exit_code, 0);
  }
  const auto budget =
      run_command("/usr/bin/python3 " + kBudgetScript + " " + wrong + " --profile rlg_navigation --check");
  std::printf("%s", budget.output.c_str());
  EXPECT_EQ(budget.exit_code, 1) << budget.output;
  EXPECT_NE(budget.output.find("NOT EXPLAINED"), std::string::npos) << budget.output;
}

}  // namespace
