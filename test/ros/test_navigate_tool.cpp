// The navigate tool, run as a user runs it, on an emulated navigation-grade IMU at rest: its errors
// against the truth stay where the nav core's error model puts them. The prediction uses the
// sensor errors the bag actually holds (measured minus truth, averaged over the same samples), so
// it is exact to first order, not a fudge factor.
#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <utility>

#include "imu_lab/common/stamps.h"
#include "imu_lab/identify/noise_report.h"
#include "imu_lab/nav/alignment_error_budget.h"
#include "imu_lab/nav/earth_model.h"
#include "imu_lab/pipeline/navigation_csv.h"
#include "imu_lab/pipeline/navigation_settings.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "ros_test_support.h"

#ifndef IMU_LAB_CONFIG_DIR
#define IMU_LAB_CONFIG_DIR "config"
#endif
#ifndef IMU_LAB_TEST_DATA_DIR
#define IMU_LAB_TEST_DATA_DIR "test/data"
#endif

namespace {

using imu_lab::test_support::contains;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;

constexpr double kArcsecPerRad = 180.0 / M_PI * 3600.0;
constexpr double kAlignmentS = 300.0;
constexpr double kNavigationS = 300.0;
// rlg_navigation's white-noise densities (rad/sqrt(s), m/s/sqrt(s)) and accelerometer bias instability.
constexpr double kGyroRandomWalk = 2.9e-7;
constexpr double kAccelRandomWalk = 5.0e-5;
constexpr double kAccelBiasInstability_m_s2 = 5.0e-5;

// Columns of the error CSV by name.
std::vector<std::map<std::string, double>> read_error_csv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::map<std::string, double> row;
    std::string cell;
    for (std::size_t i = 0; std::getline(cells, cell, ','); ++i) row[names.at(i)] = std::stod(cell);
    rows.push_back(row);
  }
  return rows;
}

// Sensor errors the bag holds: mean of measured minus true rate and specific force over (from, to].
struct MeanSensorError {
  Eigen::Vector3d gyro_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_m_s2 = Eigen::Vector3d::Zero();
  imu_lab::io::TruthRecord truth;
};

MeanSensorError mean_sensor_error(const std::string& bag, std::int64_t from_ns, std::int64_t to_ns) {
  std::map<std::int64_t, imu_lab::io::TruthRecord> truth;
  imu_lab::ros_io::for_each_truth(bag, "/imu/truth", [&](const auto& record) { truth[record.stamp_ns] = record; });
  MeanSensorError mean;
  std::size_t count = 0;
  imu_lab::ros_io::for_each_imu(bag, "/imu/raw", [&](const imu_lab::io::ImuRecord& record) {
    if (record.stamp_ns <= from_ns || record.stamp_ns > to_ns) return;
    const auto& t = truth.at(record.stamp_ns);
    mean.gyro_rad_s += record.angular_rate_rad_s - t.angular_rate_rad_s;
    mean.accel_m_s2 += record.specific_force_m_s2 - t.specific_force_m_s2;
    mean.truth = t;
    ++count;
  });
  mean.gyro_rad_s /= count;
  mean.accel_m_s2 /= count;
  return mean;
}

class NavigateTool : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = new std::string(scratch_directory());
    const auto made = run_tool(
        "emulate", "--profile " + std::string(IMU_LAB_CONFIG_DIR) + "/sensors/rlg_navigation.yaml --scenario " +
                       IMU_LAB_CONFIG_DIR + "/scenarios/static_latitude_50.yaml --duration-s " +
                       std::to_string(kAlignmentS + kNavigationS) + " --rate-hz 100 --seed 11 --out " + bag());
    ASSERT_EQ(made.exit_code, 0) << made.output;
  }
  static std::string bag() { return *directory_ + "/rlg_static.bag"; }
  static std::string* directory_;
};
std::string* NavigateTool::directory_ = nullptr;

TEST_F(NavigateTool, AlignmentAndNavigationErrorsStayWithinTheNavCorePrediction) {
  const std::string out = *directory_ + "/trajectory.csv";
  const auto run = run_tool("navigate", bag() + " --out " + out + " --every-s 1 --alignment-duration-s 300");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::printf("%s", run.output.c_str());
  const auto trajectory = imu_lab::pipeline::read_trajectory_csv(out);
  const auto errors = read_error_csv(*directory_ + "/trajectory_errors.csv");
  ASSERT_EQ(errors.size(), trajectory.size());
  ASSERT_NEAR(errors.back().at("time_since_alignment_s"), kNavigationS, 1.5);

  // Alignment: the first-order budget of alignment_error_budget.h with the bag's own sensor errors
  // over the alignment window (biases, scale factors and the noise of that window).
  const std::int64_t alignment_end_ns = trajectory.front().stamp_ns;
  const MeanSensorError during_alignment = mean_sensor_error(bag(), 0, alignment_end_ns);
  const imu_lab::nav::EarthModel earth;
  const double latitude = during_alignment.truth.latitude_rad;
  const Eigen::Vector3d predicted = imu_lab::nav::predicted_alignment_error_rad(
      during_alignment.gyro_rad_s, during_alignment.accel_m_s2, during_alignment.truth.q_body_to_enu, latitude,
      earth.gravity_m_s2(latitude, during_alignment.truth.height_m), earth.earth_rate_rad_s());
  const Eigen::Vector3d measured(errors.front().at("attitude_error_east_rad"),
                                 errors.front().at("attitude_error_north_rad"),
                                 errors.front().at("attitude_error_up_rad"));
  std::printf("[navigate] alignment error (arcsec, E N U): measured %.3f %.3f %.3f, predicted %.3f %.3f %.3f\n",
              measured.x() * kArcsecPerRad, measured.y() * kArcsecPerRad, measured.z() * kArcsecPerRad,
              predicted.x() * kArcsecPerRad, predicted.y() * kArcsecPerRad, predicted.z() * kArcsecPerRad);
  EXPECT_GT(predicted.norm() * kArcsecPerRad, 3.0);  // the comparison is not vacuous
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(measured[axis], predicted[axis], 0.01 * std::abs(predicted[axis]) + 0.05 / kArcsecPerRad)
        << "axis " << axis;
  }

  // Navigation: a self-aligned static system cancels the constant horizontal accelerometer bias
  // (by the tilt) and the east gyro bias (by the heading); what remains is the north gyro bias,
  // which tilts the platform at a constant rate: east error g e_N t^3 / 6 (well inside the Schuler
  // period), plus the white noise's random walks (3 sigma) and the accelerometer bias instability.
  const MeanSensorError during_navigation = mean_sensor_error(bag(), alignment_end_ns, trajectory.back().stamp_ns);
  const Eigen::Vector3d gyro_drift_enu = during_navigation.truth.q_body_to_enu * during_navigation.gyro_rad_s;
  const Eigen::Vector3d accel_error_enu = during_navigation.truth.q_body_to_enu * during_navigation.accel_m_s2;
  const double g = earth.gravity_m_s2(latitude, during_navigation.truth.height_m);
  const double height_time_constant_s = 30.0;  // the held channel's default loop
  double worst_ratio = 0.0;
  for (const auto& row : errors) {
    const double t = row.at("time_since_alignment_s");
    const double horizontal_bound = g * gyro_drift_enu.head<2>().norm() * t * t * t / 6.0 +
                                    3.0 * (g * kGyroRandomWalk * std::pow(t, 2.5) / std::sqrt(20.0) +
                                           kAccelRandomWalk * std::pow(t, 1.5) / std::sqrt(3.0)) +
                                    3.0 * kAccelBiasInstability_m_s2 * t * t / 2.0 + 0.01;
    EXPECT_LE(row.at("horizontal_position_error_m"), horizontal_bound) << "at t = " << t << " s";
    worst_ratio = std::max(worst_ratio, row.at("horizontal_position_error_m") / horizontal_bound);
    // Held vertical channel (vertical_channel.h): |h error| <= |b| tau^2, b the vertical error.
    const double height_bound = (std::abs(accel_error_enu.z()) + 3.0 * kAccelBiasInstability_m_s2) *
                                height_time_constant_s * height_time_constant_s;
    EXPECT_LE(std::abs(row.at("height_error_m")), height_bound) << "at t = " << t << " s";
  }
  std::printf("[navigate] horizontal error %.3f m after %.0f s; worst fraction of its bound %.2f\n",
              errors.back().at("horizontal_position_error_m"), errors.back().at("time_since_alignment_s"), worst_ratio);
  EXPECT_GT(errors.back().at("horizontal_position_error_m"), 0.05);  // the bound is not met trivially
  // Heading drifts only by the up gyro bias: far below the alignment error.
  EXPECT_NEAR(errors.back().at("attitude_error_up_rad"), measured.z(), 5.0 / kArcsecPerRad);
}

// -o into a folder that does not exist yet (issue 46: "cannot create nav/u4_traj.csv.new.tmp"):
// the folder is made and the trajectory and its errors written there.
TEST_F(NavigateTool, CreatesTheOutputFolder) {
  const std::string out = *directory_ + "/new_folder/nav/trajectory.csv";
  const auto run = run_tool("navigate", bag() + " --alignment-duration-s 300 --every-s 100 --out " + out);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_FALSE(imu_lab::pipeline::read_trajectory_csv(out).empty());
  EXPECT_TRUE(imu_lab::test_support::file_exists(*directory_ + "/new_folder/nav/trajectory_errors.csv"));
}

// Bad input: a clear message naming the bag and the problem, a non-zero exit, and no CSV at all.
void expect_refused(const std::string& arguments, const std::string& out, const std::string& expected_text) {
  const auto run = run_tool("navigate", arguments + " --out " + out);
  EXPECT_NE(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find(expected_text), std::string::npos) << run.output;
  EXPECT_FALSE(imu_lab::test_support::file_exists(out));
  EXPECT_FALSE(imu_lab::test_support::file_exists(out.substr(0, out.size() - 4) + "_errors.csv"));
}

// Copies the first `count` /imu/raw and /imu/truth messages of the suite's bag, setting the
// angular rate (y) of message `bad_index` to `bad_value`; returns the target and that message's stamp.
std::pair<std::string, std::int64_t> copy_with_bad_value(const std::string& source, const std::string& target,
                                                         int count, int bad_index, double bad_value) {
  rosbag::Bag in(source, rosbag::bagmode::Read);
  rosbag::Bag out(target, rosbag::bagmode::Write);
  int written = 0;
  std::int64_t bad_stamp_ns = 0;
  rosbag::View view(in, rosbag::TopicQuery(std::vector<std::string>{"/imu/raw", "/imu/truth"}));
  for (const rosbag::MessageInstance& instance : view) {
    if (const auto imu = instance.instantiate<sensor_msgs::Imu>()) {
      sensor_msgs::Imu copy = *imu;
      if (written++ == bad_index) {
        copy.angular_velocity.y = bad_value;
        copy.linear_acceleration.z = bad_value;
        bad_stamp_ns = static_cast<std::int64_t>(copy.header.stamp.toNSec());
      }
      if (written > count) break;
      out.write(instance.getTopic(), instance.getTime(), copy);
    } else {
      out.write(instance.getTopic(), instance.getTime(), instance);
    }
  }
  return {target, bad_stamp_ns};
}

TEST_F(NavigateTool, RefusesABagWithoutAnImuTopic) {
  const std::string bag_path = *directory_ + "/no_imu.bag";
  {
    rosbag::Bag bag(bag_path, rosbag::bagmode::Write);
    sensor_msgs::Temperature temperature;
    temperature.header.stamp.fromSec(10.0);
    bag.write("/imu/temperature", temperature.header.stamp, temperature);
  }
  expect_refused(bag_path + " --latitude-deg 50 --longitude-deg 10 --height-m 0", *directory_ + "/no_imu.csv",
                 "has no sensor_msgs/Imu topic");
}

TEST_F(NavigateTool, RefusesATruncatedBag) {
  const std::string truncated = *directory_ + "/truncated.bag";
  const std::string bytes = imu_lab::test_support::read_file(bag());
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  expect_refused(truncated + " --alignment-duration-s 10", *directory_ + "/truncated.csv", "truncated.bag");
}

TEST_F(NavigateTool, RefusesNaNSamplesUnlessAskedToSkipThem) {
  const std::string with_nan = copy_with_bad_value(bag(), *directory_ + "/nan.bag", 3000, 2000, std::nan("")).first;
  const std::string arguments = with_nan + " --alignment-duration-s 10";
  expect_refused(arguments, *directory_ + "/nan.csv", "NaN");
  const auto skipped = run_tool("navigate", arguments + " --skip-bad-samples --out " + *directory_ + "/nan.csv");
  EXPECT_EQ(skipped.exit_code, 0) << skipped.output;
  EXPECT_NE(skipped.output.find("skipped 1 invalid"), std::string::npos) << skipped.output;
  EXPECT_TRUE(imu_lab::test_support::file_exists(*directory_ + "/nan.csv"));
}

TEST_F(NavigateTool, RefusesABagTooShortForTheAlignment) {
  expect_refused(bag() + " --alignment-duration-s 5000", *directory_ + "/short.csv", "alignment needs 5000");
}

// Finite but absurd values within +-1e100 (1e50 rad/s and m/s^2; beyond it a sample is refused as
// invalid, like NaN) make the navigation state unusable: refused, exit 1,
// naming the bag and the stamp where it happened, and nothing written (it once wrote rows of NaN
// latitude and exited 0).
TEST_F(NavigateTool, RefusesABagThatMakesTheStateUnusable) {
  const auto [absurd, stamp_ns] = copy_with_bad_value(bag(), *directory_ + "/absurd.bag", 3000, 2000, 1e50);
  const std::string out = *directory_ + "/absurd.csv";
  const auto run = run_tool("navigate", absurd + " --alignment-duration-s 10 --out " + out);
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("absurd.bag"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("unusable at stamp " + imu_lab::format_stamp_s(stamp_ns)), std::string::npos) << run.output;
  EXPECT_FALSE(imu_lab::test_support::file_exists(out));
  EXPECT_FALSE(imu_lab::test_support::file_exists(*directory_ + "/absurd_errors.csv"));
}

// --no-align without truth needs the initial velocity; a malformed one, or one given with an
// alignment (which starts at rest), is a bad configuration: exit 2 naming the option.
TEST_F(NavigateTool, RefusesAStartWithoutAlignmentWithoutAVelocity) {
  const std::string out = *directory_ + "/no_velocity.csv";
  const std::string position = " --latitude-deg 50 --longitude-deg 10 --height-m 0";
  const auto expect_bad_configuration = [&](const std::string& arguments) {
    const auto run = run_tool("navigate", bag() + position + " " + arguments + " --out " + out);
    EXPECT_EQ(run.exit_code, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find("--initial-velocity-enu-m-s"), std::string::npos) << run.output;
    EXPECT_FALSE(imu_lab::test_support::file_exists(out));
  };
  expect_bad_configuration("--no-align --truth-topic /no_truth_here");  // as a bag without truth
  expect_bad_configuration("--no-align --initial-velocity-enu-m-s 1,0");
  expect_bad_configuration("--no-align --initial-velocity-enu-m-s 1,nan,0");
  expect_bad_configuration("--no-align --initial-velocity-enu-m-s 1,0,0,0");
  expect_bad_configuration("--initial-velocity-enu-m-s 0.5,0,0");
  const auto given =
      run_tool("navigate", bag() + position +
                               " --no-align --truth-topic /no_truth_here --initial-velocity-enu-m-s 0,0,0 "
                               "--every-s 100 --out " +
                               out);
  EXPECT_EQ(given.exit_code, 0) << given.output;
}

// The expected_* options of the node, on the tool: the alignment's predicted error is printed when
// it can be (sigma_E = sigma_N = b / g with only an accelerometer bias given,
// alignment_error_budget.h), and the tool says what is missing when it cannot.
TEST_F(NavigateTool, PrintsThePredictedAlignmentErrorFromTheExpectedErrors) {
  const std::string out = *directory_ + "/predicted.csv";
  const auto without = run_tool("navigate", bag() + " --alignment-duration-s 300 --every-s 100 --out " + out);
  ASSERT_EQ(without.exit_code, 0) << without.output;
  EXPECT_NE(without.output.find(
                "no predicted error (give allan's noise report, --noise noise.yaml, or the expected sensor errors"),
            std::string::npos)
      << without.output;
  const double accel_bias_m_s2 = 5e-5;
  const auto with =
      run_tool("navigate", bag() + " --alignment-duration-s 300 --every-s 100 --expected-accel-bias-m-s2 " +
                               std::to_string(accel_bias_m_s2) + " --out " + out);
  ASSERT_EQ(with.exit_code, 0) << with.output;
  const std::string label = "predicted 1-sigma error E/N/U ";
  const auto at = with.output.find(label);
  ASSERT_NE(at, std::string::npos) << with.output;
  double east_arcsec = 0.0, north_arcsec = 0.0;
  ASSERT_EQ(std::sscanf(with.output.c_str() + at + label.size(), "%lf %lf", &east_arcsec, &north_arcsec), 2);
  const double g = imu_lab::nav::EarthModel().gravity_m_s2(50.0 * M_PI / 180.0, 0.0);
  EXPECT_NEAR(east_arcsec, accel_bias_m_s2 / g * kArcsecPerRad, 0.01 * accel_bias_m_s2 / g * kArcsecPerRad);
  EXPECT_NEAR(north_arcsec, east_arcsec, 0.01 * east_arcsec);
  const auto negative = run_tool("navigate", bag() + " --expected-gyro-bias-rad-s -1 --out " + out);
  EXPECT_EQ(negative.exit_code, 2) << negative.output;
}

// The predicted 1-sigma alignment error printed: E/N/U in arcsec, empty when not printed.
std::vector<double> printed_prediction_arcsec(const std::string& output) {
  const std::string label = "predicted 1-sigma error E/N/U ";
  const auto at = output.find(label);
  if (at == std::string::npos) return {};
  std::vector<double> arcsec(3);
  if (std::sscanf(output.c_str() + at + label.size(), "%lf %lf %lf", &arcsec[0], &arcsec[1], &arcsec[2]) != 3)
    return {};
  return arcsec;
}

// Issue 46: the expected errors from allan's noise report (--noise): per triad the largest axis's
// white noise density and bias instability, read here by key, give the same prediction as the
// four options given those numbers; an option given beside --noise wins. A heading whose predicted
// sigma exceeds 1 rad (a MEMS gyro's bias of 0.4 deg/s, 7e-3 rad/s, against the Earth rate's
// horizontal part) is said to be not observable; the tactical MEMS gyros' bias instability alone
// (a few degrees) is not.
TEST(NavigateToolNoiseReport, TakesTheExpectedErrorsFromTheNoiseReportAndSaysWhenHeadingIsNotObservable) {
  const std::string directory = scratch_directory();
  const std::string bag = directory + "/mems_static.bag";
  const auto made = run_tool("emulate", "--profile " + std::string(IMU_LAB_CONFIG_DIR) +
                                            "/sensors/tactical_mems.yaml --scenario " + IMU_LAB_CONFIG_DIR +
                                            "/scenarios/static_latitude_50.yaml --duration-s 600 --rate-hz 100 "
                                            "--seed 12 --out " +
                                            bag);
  ASSERT_EQ(made.exit_code, 0) << made.output;
  const std::string report = directory + "/allan_report";
  const auto analysed = run_tool("allan", bag + " --topic /imu/raw --no-plot --out " + report);
  ASSERT_EQ(analysed.exit_code, 0) << analysed.output;
  const auto values = imu_lab::identify::read_noise_report_file(report + "/noise.yaml");
  // Over a triad's axes, the largest of a term's key and (for the white density, with the output's
  // quantisation density step sqrt(tau0 / 12) added in power) of the front end's.
  const auto largest = [&](const std::string& triad, const std::string& term, const std::string& key,
                           const std::string& step_key) {
    double value = 0.0;
    for (const std::string axis : {"_x", "_y", "_z"}) {
      const std::string prefix = "triads." + triad + ".axes." + triad + axis + ".";
      const auto found = values.find(prefix + "terms." + term + "." + key);
      double squared = found == values.end() ? 0.0 : found->second * found->second;
      const auto step = values.find(prefix + "front_end." + step_key);
      if (step != values.end()) squared += step->second * step->second * values.at(prefix + "tau0_s") / 12.0;
      value = std::max(value, std::sqrt(squared));
    }
    return value;
  };
  const double gyro_white = largest("gyro", "white_rate", "N_rad_s_per_sqrt_hz", "output_quantization_step_rad_s");
  const double gyro_bias = largest("gyro", "bias_instability", "B_rad_s", "");
  const double accel_white = largest("accel", "white_rate", "N_m_s2_per_sqrt_hz", "output_quantization_step_m_s2");
  const double accel_bias = largest("accel", "bias_instability", "B_m_s2", "");
  ASSERT_GT(gyro_white, 0.0);
  ASSERT_GT(accel_white, 0.0);
  const std::string out = directory + "/from_report.csv";
  const std::string common = bag + " --alignment-duration-s 300 --every-s 100 --out " + out;
  const auto from_report = run_tool("navigate", common + " --noise " + report + "/noise.yaml");
  ASSERT_EQ(from_report.exit_code, 0) << from_report.output;
  char given[512];
  std::snprintf(given, sizeof given,
                " --expected-gyro-bias-rad-s %.17g --expected-accel-bias-m-s2 %.17g "
                "--gyro-noise-density-rad-s-per-sqrt-hz %.17g --accel-noise-density-m-s2-per-sqrt-hz %.17g",
                gyro_bias, accel_bias, gyro_white, accel_white);
  const auto from_options = run_tool("navigate", common + given);
  ASSERT_EQ(from_options.exit_code, 0) << from_options.output;
  const auto predicted = printed_prediction_arcsec(from_report.output);
  ASSERT_EQ(predicted.size(), 3u) << from_report.output;
  EXPECT_EQ(predicted, printed_prediction_arcsec(from_options.output)) << from_report.output << from_options.output;
  EXPECT_FALSE(contains(from_report.output, "heading not observable")) << from_report.output;

  const auto mems_bias =
      run_tool("navigate", common + " --noise " + report + "/noise.yaml --expected-gyro-bias-rad-s 7e-3");
  ASSERT_EQ(mems_bias.exit_code, 0) << mems_bias.output;
  const auto mems_predicted = printed_prediction_arcsec(mems_bias.output);
  ASSERT_EQ(mems_predicted.size(), 3u) << mems_bias.output;
  EXPECT_GT(mems_predicted[2], 206265.0) << mems_bias.output;  // over 1 rad
  EXPECT_EQ(mems_predicted[0], predicted[0]) << "the gyro bias does not tilt";
  EXPECT_TRUE(contains(mems_bias.output, "heading not observable")) << mems_bias.output;

  const auto missing = run_tool("navigate", common + " --noise " + directory + "/no_such_noise.yaml");
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_TRUE(contains(missing.output, "no_such_noise.yaml")) << missing.output;
}

// Through the binary, with either input: without alignment the start state is the truth's at the
// first sample (position, attitude, velocity), and the increment ending there is not integrated.
// The error-free IMU coning at 200 Hz for 30 s then ends within the 5 cm test_navigate_ideal.cpp
// requires; a start one interval early costs metres here.
TEST(NavigateToolStart, StartsFromTheTruthAtTheFirstSampleWithEitherInput) {
  const std::string directory = scratch_directory();
  const std::string coning = directory + "/coning.bag";
  const auto made = run_tool("emulate", "--profile " + std::string(IMU_LAB_CONFIG_DIR) +
                                            "/sensors/ideal.yaml --scenario " + IMU_LAB_CONFIG_DIR +
                                            "/scenarios/coning.yaml --duration-s 30 --rate-hz 200 --out " + coning);
  ASSERT_EQ(made.exit_code, 0) << made.output;
  for (const std::string input : {"imu", "increment"}) {
    const std::string out = directory + "/" + input + ".csv";
    const auto run = run_tool("navigate", coning + " --no-align --input-type " + input + " --out " + out);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("attitude from the truth, velocity from the truth, position from the truth"),
              std::string::npos)
        << run.output;
    const auto errors = read_error_csv(directory + "/" + input + "_errors.csv");
    ASSERT_FALSE(errors.empty());
    const auto& first = errors.front();
    const auto& last = errors.back();
    EXPECT_EQ(first.at("time_since_alignment_s"), 0.0);
    EXPECT_EQ(first.at("horizontal_position_error_m"), 0.0);
    EXPECT_NEAR(last.at("time_since_alignment_s"), 30.0 - 0.005, 1e-9);
    std::printf("[navigate] ideal coning 30 s, %s input: final position error %.3g m\n", input.c_str(),
                std::hypot(last.at("horizontal_position_error_m"), last.at("height_error_m")));
    EXPECT_LT(std::hypot(last.at("horizontal_position_error_m"), last.at("height_error_m")), 0.05);
  }
}

// Must-show: the textbook's single-channel error of an initial velocity error, through the tool.
// On the non-rotating sphere at rest (error-free IMU), a start at v0 = 1 m/s east gives
// east error (v0 / w0) sin(w0 t), w0 = sqrt(g / R) (Fomichev 2022 eq. 23; test_nav_schuler.cpp on the
// core), and no north error; every output sample over 90 minutes within 2 % of the peak v0 / w0.
TEST(NavigateToolSchuler, InitialVelocityErrorGivesTheSingleChannelSine) {
  const std::string directory = scratch_directory();
  const std::string at_rest = directory + "/sphere.bag";
  const auto made =
      run_tool("emulate", "--profile " + std::string(IMU_LAB_CONFIG_DIR) + "/sensors/ideal.yaml --scenario " +
                              IMU_LAB_TEST_DATA_DIR + "/nav/static_sphere.yaml --rate-hz 10 --out " + at_rest);
  ASSERT_EQ(made.exit_code, 0) << made.output;
  const std::string out = directory + "/trajectory.csv";
  const auto run = run_tool("navigate", at_rest +
                                            " --earth-model sphere --no-align --initial-velocity-enu-m-s 1,0,0 "
                                            "--every-s 10 --out " +
                                            out);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto errors = read_error_csv(directory + "/trajectory_errors.csv");
  const imu_lab::nav::EarthModelConfig sphere = imu_lab::pipeline::parse_earth_model("sphere", "sphere");
  const double w0 = imu_lab::nav::EarthModel(sphere).schuler_rate_rad_s();
  const double v0_m_s = 1.0, peak_m = v0_m_s / w0;
  ASSERT_GE(errors.size(), 540u);
  ASSERT_GE(errors.back().at("time_since_alignment_s"), 5390.0);
  double worst_m = 0.0, largest_east_m = 0.0;
  for (const auto& row : errors) {
    const double t = row.at("time_since_alignment_s");
    const double deviation_m = std::hypot(row.at("east_error_m") - peak_m * std::sin(w0 * t), row.at("north_error_m"));
    worst_m = std::max(worst_m, deviation_m);
    largest_east_m = std::max(largest_east_m, std::abs(row.at("east_error_m")));
    EXPECT_LE(deviation_m, 0.02 * peak_m) << "at t = " << t << " s";
  }
  std::printf(
      "[navigate] v0 = 1 m/s on the sphere: peak v0/w0 %.1f m, largest east error %.1f m, worst deviation "
      "from the sine %.3g m (%.3g %% of the peak)\n",
      peak_m, largest_east_m, worst_m, 100.0 * worst_m / peak_m);
  EXPECT_GT(largest_east_m, 0.98 * peak_m);  // the sine is really there
}

}  // namespace
