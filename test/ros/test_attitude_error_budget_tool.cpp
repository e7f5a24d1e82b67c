// attitude_error_budget as a user runs it: `allan`'s noise report of an emulated bag (gyros with
// white rate and random walk) and a motion in, the CSV out.
// - On the platform the total (root-sum-square over the ENU axes) is the closed form
//   sqrt(sum_i N_i^2 t + K_i^2 t^3 / 3) of the report's own values (the Earth rate turns the error
//   without changing its total); a body whose axes stay on ENU's gives the strapdown system the
//   platform's figures; the rate table's spin lowers the strapdown total below the platform's.
// - The motion a recording's gyros measured (an ideal IMU on the rate table) gives the scenario's
//   own prediction.
// - Bad input: options exit 2 naming the option, data exit 1 naming the file, nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "imu_lab/identify/noise_report.h"
#include "imu_lab/identify/units.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::file_exists;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;

std::vector<std::vector<double>> csv_rows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);  // header
  while (std::getline(lines, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

class AttitudeErrorBudgetTool : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = scratch_directory();
    const std::string profile = directory_ + "/gyros.yaml";
    const std::string zero = "[[0, 0, 0], [0, 0, 0], [0, 0, 0]]";
    std::ofstream(profile) << "name: white_and_walk\ngyro:\n  bias_fixed_rad_s: 0.0\n  bias_turn_on_sigma_rad_s: 0.0\n"
                           << "  scale_factor_error_ppm: 0.0\n  misalignment_rad: " << zero << "\n  noise:\n"
                           << "    white_rate: {density_rad_s_per_sqrt_hz: 1.0e-4}\n"
                           << "    random_walk: {density_rad_s_per_sqrt_s: 2.0e-5}\n"
                           << "accelerometer:\n  bias_fixed_m_s2: 0.0\n  bias_turn_on_sigma_m_s2: 0.0\n"
                           << "  scale_factor_error_ppm: 0.0\n  misalignment_rad: " << zero << "\n  noise:\n"
                           << "    white_rate: {density_m_s2_per_sqrt_hz: 1.0e-3}\n";
    const std::string bag = directory_ + "/gyros.bag";
    const auto made = run_tool(
        "emulate", "--profile " + profile + " --duration-s 600 --rate-hz 50 --seed 19 --no-truth --out " + bag);
    ASSERT_EQ(made.exit_code, 0) << made.output;
    const auto run = run_tool("allan", bag + " --topic /imu/raw --no-plot --out " + directory_ + "/report");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    noise_ = directory_ + "/report/noise.yaml";
  }

  static std::string directory_;
  static std::string noise_;

 public:
  static const std::string& noise() { return noise_; }
};

std::string AttitudeErrorBudgetTool::directory_;
std::string AttitudeErrorBudgetTool::noise_;

// The tool's CSV rows on the suite's noise report; none when it fails.
std::vector<std::vector<double>> budget_rows(const std::string& arguments, const std::string& csv) {
  const auto run =
      run_tool("attitude_error_budget", "--noise " + AttitudeErrorBudgetTool::noise() + " " + arguments + " -o " + csv);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return run.exit_code == 0 ? csv_rows(read_file(csv)) : std::vector<std::vector<double>>{};
}

TEST_F(AttitudeErrorBudgetTool, PlatformIsTheClosedFormAndTheSpinLowersTheStrapdownTotal) {
  const auto values = imu_lab::identify::read_noise_report_values(read_file(noise_));
  double white = 0.0, walk = 0.0;  // sums over the axes of N^2 and K^2
  for (const char* axis : {"gyro_x", "gyro_y", "gyro_z"}) {
    const std::string terms = std::string("triads.gyro.axes.") + axis + ".terms.";
    ASSERT_EQ(values.count(terms + "white_rate.N_rad_s_per_sqrt_hz"), 1u) << axis;
    ASSERT_EQ(values.count(terms + "random_walk.K_rad_s_per_sqrt_s"), 1u) << axis << ": random walk not identified";
    ASSERT_EQ(values.count(terms + "bias_instability.B_rad_s"), 0u) << axis << ": a bias instability was identified";
    white += std::pow(values.at(terms + "white_rate.N_rad_s_per_sqrt_hz"), 2);
    walk += std::pow(values.at(terms + "random_walk.K_rad_s_per_sqrt_s"), 2);
  }
  const auto rows = budget_rows("--scenario rate_table --duration-s 300 --step-s 0.02 --output-interval-s 10",
                                directory_ + "/table.csv");
  ASSERT_EQ(rows.size(), 31u);
  for (const auto& row : rows) {
    const double t = row[0];
    // 1e-3: a fitted front-end low-pass (T_c about 1 ms) takes N^2 T_c from N^2 t.
    EXPECT_NEAR(row[8], std::sqrt(white * t + walk * t * t * t / 3.0), 1e-12 + 1e-3 * row[8]) << "t = " << t;
  }
  // The table turns about Up (at 10 deg/s from 120 s, 100 deg/s from 240 s): the random walk across
  // the spin averages.
  EXPECT_LT(rows.back()[7], 0.8 * rows.back()[8]);

  for (const auto& row : budget_rows("--body-rate-deg-s 0 0 0 --latitude-deg 50 --duration-s 100 "
                                     "--output-interval-s 50",
                                     directory_ + "/still.csv")) {
    for (int axis = 1; axis <= 3; ++axis) EXPECT_NEAR(row[axis], row[axis + 3], 1e-12 * row[axis + 3]);
  }
}

TEST_F(AttitudeErrorBudgetTool, RecordedRatesGiveTheScenariosPrediction) {
  const std::string bag = directory_ + "/table.bag";
  const auto made = run_tool("emulate",
                             "--profile ideal --scenario rate_table --duration-s 300 --rate-hz 50 "
                             "--no-truth --no-increments --out " +
                                 bag);
  ASSERT_EQ(made.exit_code, 0) << made.output;
  const std::string grid = " --duration-s 290 --step-s 0.02 --output-interval-s 10";
  const auto recorded = budget_rows("--motion-bag " + bag + " --start-rpy-deg 0 0 90 --latitude-deg 50.45" + grid,
                                    directory_ + "/recorded.csv");
  const auto scenario = budget_rows("--scenario rate_table" + grid, directory_ + "/scenario.csv");
  ASSERT_EQ(recorded.size(), 30u);
  ASSERT_EQ(recorded.size(), scenario.size());
  // The recording starts one sample (0.02 s) after the scenario: at 100 deg/s its attitude leads
  // by a 2 deg turn about Up, which moves error between East and North but leaves the Up axis and
  // the totals (traces) unchanged up to the axes' different N and K (a few %) times sin^2(2 deg).
  for (std::size_t k = 0; k < recorded.size(); ++k) {
    EXPECT_NEAR(recorded[k][0], scenario[k][0], 1e-9);
    for (int column : {3, 6, 7, 8}) {
      EXPECT_NEAR(recorded[k][column], scenario[k][column], 1e-12 + 1e-3 * scenario[k][column])
          << "t = " << scenario[k][0] << " column " << column;
    }
  }
  // The spin shows: strapdown total well below the platform's by the end, as on the scenario.
  EXPECT_LT(recorded.back()[7], 0.8 * recorded.back()[8]);
}

TEST_F(AttitudeErrorBudgetTool, RefusesBadOptionsAndBadReportsWritingNothing) {
  const std::string out = scratch_directory() + "/budget.csv";
  const std::string motion = " --body-rate-deg-s 0 0 10 --duration-s 10 -o " + out;
  const auto expect_refused = [&](const std::string& arguments, int exit_code, const std::string& word) {
    const auto run = run_tool("attitude_error_budget", arguments);
    EXPECT_EQ(run.exit_code, exit_code) << arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(word), std::string::npos) << "no '" << word << "' in\n" << run.output;
    EXPECT_FALSE(file_exists(out)) << arguments;
  };
  expect_refused(motion, 2, "--noise");
  expect_refused("--noise " + noise_ + " --scenario static" + motion, 2, "--scenario/--body-rate-deg-s");
  expect_refused("--noise " + noise_ + " --scenario static --start-rpy-deg 0 0 1 -o " + out, 2, "--start-rpy-deg");
  expect_refused("--noise " + noise_ + " --motion-topic /imu/raw" + motion, 2, "--motion-topic");
  const std::string not_a_bag = directory_ + "/not_a.bag";
  std::ofstream(not_a_bag) << "no bag\n";
  expect_refused("--noise " + noise_ + " --motion-bag " + not_a_bag + " -o " + out, 1, not_a_bag);
  expect_refused("--noise " + noise_ + " --body-rate-deg-s 0 0 10 -o " + out, 2, "--duration-s");
  expect_refused("--noise " + noise_ + " --step-s 0.001" + motion, 2, "--step-s");
  expect_refused("--noise " + noise_ + " --duration-s -1 --body-rate-deg-s 0 0 1 -o " + out, 2, "--duration-s");
  const std::string missing = directory_ + "/missing.yaml";
  expect_refused("--noise " + missing + motion, 1, missing);
  const std::string garbage = directory_ + "/garbage.yaml";
  std::ofstream(garbage) << "format: something_else\n";
  expect_refused("--noise " + garbage + motion, 1, garbage);
  // A term the prediction has no model for: the report's white rate renamed a zero-DC family.
  std::string text = read_file(noise_);
  const std::string renamed = directory_ + "/zero_dc.yaml";
  const std::size_t at = text.find("          white_rate:");
  ASSERT_NE(at, std::string::npos);
  using imu_lab::identify::TermKind;
  const std::string amplitude = imu_lab::identify::parameter_key(
      imu_lab::identify::amplitude_symbol(TermKind::kZeroDcFamily),
      imu_lab::identify::amplitude_units(imu_lab::identify::SensorKind::kGyroscope, TermKind::kZeroDcFamily)[0].key);
  const std::string shape =
      imu_lab::identify::parameter_key(imu_lab::identify::shape_symbol(TermKind::kZeroDcFamily),
                                       imu_lab::identify::shape_units(TermKind::kZeroDcFamily)[0].key);
  text.replace(at, std::string("          white_rate:").size(),
               "          zero_dc_family:\n            " + amplitude + ": 1.0e-6\n            " + shape + ": 0.1");
  std::ofstream(renamed) << text;
  expect_refused("--noise " + renamed + motion, 1, "zero_dc_family");
}

}  // namespace
