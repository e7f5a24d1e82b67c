// The correct tool on the end-to-end test's sensor (test/data/chain/uncalibrated_mems.yaml): the
// thermal model and the calibration are fitted by the tools from emulated tests as in
// full_chain.test, then a static bag at 45 degC (25 degC from the calibration's temperature) is
// corrected. Its mean angular rate and specific force must come to the truth (Earth rate,
// gravity) within what the correction cannot know, and far closer than the raw means.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "ros_test_support.h"

namespace {

using namespace imu_lab::test_support;  // NOLINT: the scratch and tool helpers

const std::string kChainData = std::string(IMU_LAB_TEST_DATA_DIR) + "/chain";
constexpr double kStaticDuration_s = 300.0;

// From uncalibrated_mems.yaml, per axis (one sigma or density):
struct TriadNoise {
  double turn_on_sigma;     // drawn anew per run: the static run's differs from the calibration run's
  double bias_instability;  // B: the flicker floor; the bias wanders by about B between runs
  double white_density;     // N: the mean over T has N / sqrt(T)
  double random_walk;       // K: the mean over T wanders by K sqrt(T / 3)
};
constexpr TriadNoise kGyro{4.8e-6, 4.8e-6, 4.4e-5, 1.0e-7};
constexpr TriadNoise kAccelerometer{2.0e-3, 2.0e-4, 5.0e-4, 2.0e-6};

// What the corrected mean may still be off by, per axis (one sigma): the static run's turn-on bias
// and bias wander against the calibration run's (both unknown to the correction, hence twice),
// white noise and random walk over the static run, and the calibration's own 60 s dwell means.
double residual_sigma(const TriadNoise& n) {
  return std::sqrt(2.0 * n.turn_on_sigma * n.turn_on_sigma + 2.0 * n.bias_instability * n.bias_instability +
                   n.white_density * n.white_density / kStaticDuration_s +
                   n.random_walk * n.random_walk * kStaticDuration_s / 3.0 + n.white_density * n.white_density / 60.0);
}
// The error vector's norm is sigma times a chi with 3 degrees of freedom: P(chi_3 > 4.6) < 1e-4.
constexpr double kChi3Bound = 4.6;

struct Means {
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero(), specific_force_m_s2 = Eigen::Vector3d::Zero();
};

Means imu_means(const std::string& bag) {
  Means m;
  const std::size_t count = imu_lab::ros_io::for_each_imu(bag, "/imu/raw", [&](const imu_lab::io::ImuRecord& r) {
    m.angular_rate_rad_s += r.angular_rate_rad_s;
    m.specific_force_m_s2 += r.specific_force_m_s2;
  });
  m.angular_rate_rad_s /= static_cast<double>(count);
  m.specific_force_m_s2 /= static_cast<double>(count);
  return m;
}

Means truth_means(const std::string& bag) {
  Means m;
  const auto add = [&](const imu_lab::io::TruthRecord& r) {
    m.angular_rate_rad_s += r.angular_rate_rad_s;
    m.specific_force_m_s2 += r.specific_force_m_s2;
  };
  const std::size_t count = imu_lab::ros_io::for_each_truth(bag, "/imu/truth", add);
  m.angular_rate_rad_s /= static_cast<double>(count);
  m.specific_force_m_s2 /= static_cast<double>(count);
  return m;
}

void run_or_fail(const std::string& tool, const std::string& arguments) {
  const CommandResult result = run_tool(tool, arguments);
  ASSERT_EQ(result.exit_code, 0) << tool << " " << arguments << "\n" << result.output;
}

TEST(CorrectToolEmulated, StaticBagMeansComeToTheTruthFarCloserThanRaw) {
  const std::string d = scratch_directory();
  const std::string profile = " --profile " + kChainData + "/uncalibrated_mems.yaml";
  // As full_chain.test: the thermal test, the six-position calibration at 20 degC, the fits.
  run_or_fail("emulate", profile + " --scenario " + kChainData +
                             "/thermal_test.yaml --rate-hz 10 --seed 21 "
                             "--no-truth --no-increments --out " +
                             d + "/thermal.bag");
  run_or_fail("emulate", profile +
                             " --scenario multiposition_6 --rate-hz 100 --seed 22 --no-truth --no-increments "
                             "--out " +
                             d + "/calibration.bag");
  run_or_fail("fit_thermal", d +
                                 "/thermal.bag --rate-term --window-s 20 --reference-temperature-c 20 "
                                 "--latitude-deg 50.45 --height-m 180 --out " +
                                 d + "/thermal.yaml");
  run_or_fail("fit_calibration", d + "/calibration.bag --schedule multiposition_6 --out " + d + "/calibration.yaml");
  // At rest at 45 degC, body x North, at the calibration's site.
  std::ofstream(d + "/static_45c.yaml") << "type: static\nlatitude_deg: 50.45\nlongitude_deg: 30.52\nheight_m: 180.0\n"
                                           "roll_deg: 0.0\npitch_deg: 0.0\nyaw_deg: 90.0\ntemperature_c: 45.0\n"
                                           "earth_model: wgs84_rotating\nduration_s: 300.0\n";
  run_or_fail("emulate", profile + " --scenario " + d + "/static_45c.yaml --rate-hz 100 --seed 24 --no-increments " +
                             "--out " + d + "/static.bag");
  const CommandResult corrected =
      run_tool("correct", d + "/static.bag --thermal-model " + d + "/thermal.yaml " + "--calibration " + d +
                              "/calibration.yaml --out " + d + "/corrected.bag");
  ASSERT_EQ(corrected.exit_code, 0) << corrected.output;
  std::printf("%s", corrected.output.c_str());

  const Means truth = truth_means(d + "/static.bag"), raw = imu_means(d + "/static.bag"),
              fixed = imu_means(d + "/corrected.bag");
  const double gyro_bound = kChi3Bound * residual_sigma(kGyro);
  const double accel_bound = kChi3Bound * residual_sigma(kAccelerometer);
  const double gyro_raw = (raw.angular_rate_rad_s - truth.angular_rate_rad_s).norm();
  const double gyro_corrected = (fixed.angular_rate_rad_s - truth.angular_rate_rad_s).norm();
  const double accel_raw = (raw.specific_force_m_s2 - truth.specific_force_m_s2).norm();
  const double accel_corrected = (fixed.specific_force_m_s2 - truth.specific_force_m_s2).norm();
  std::printf("gyro mean error %.3g rad/s raw, %.3g corrected (bound %.3g): %.1fx\n", gyro_raw, gyro_corrected,
              gyro_bound, gyro_raw / gyro_corrected);
  std::printf("accel mean error %.3g m/s^2 raw, %.3g corrected (bound %.3g): %.1fx\n", accel_raw, accel_corrected,
              accel_bound, accel_raw / accel_corrected);
  EXPECT_LT(gyro_corrected, gyro_bound);
  EXPECT_LT(accel_corrected, accel_bound);
  // The test has power only if the raw error lies far outside that bound: the profile's fixed
  // biases, scale factors and 25 degC of thermal drift give about 6e-4 rad/s and 0.15 m/s^2,
  // over ten times the bounds (5.3e-5 rad/s, 0.013 m/s^2).
  EXPECT_GT(gyro_raw, 5.0 * gyro_bound);
  EXPECT_GT(accel_raw, 5.0 * accel_bound);
}

}  // namespace
