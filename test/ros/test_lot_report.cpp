// lot_report and repeatability --calibrations as a user runs them, on emulated units:
// - three units of one profile (different seeds), each through `allan`, then lot_report: the
//   typical white noise of each channel is the median and the worst the maximum of the units'
//   values, and the typical value lies within what the units' own sigmas allow of the profile's
//   density; the files come as one set with the plot; bad input exits 2 naming the option;
// - four emulated calibrations (different seeds), each through fit_calibration, then
//   repeatability --calibrations: the spread is the sample deviation of the files' own scale
//   factors, and their mean lies within what that spread allows of the profile's scale factors
//   and misalignments.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/identify/units.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::file_exists;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;
using imu_lab::test_support::write_quick_twelve_position_schedule;
namespace units = imu_lab::identify::units;

// config/sensors/tactical_mems.yaml: white rate densities, gyro then accelerometer, in the
// field's units (0.15 deg/sqrt(h), 0.03 m/s/sqrt(h)).
const double kGyroN_deg_per_sqrt_h = 4.4e-5 / units::kDegPerSqrtHour_rad_per_sqrt_s;
const double kAccelN_m_s_per_sqrt_h = 5.0e-4 / units::kMeterPerSecondPerSqrtHour_m_s2_per_sqrt_hz;
// Its scale-factor errors [ppm], gyro x..z then accelerometer x..z, at the calibration scenario's
// 20 degC: the profile's values at 25 degC plus its thermal polynomial at dT = -5 degC (gyro
// 10, -8, 12 ppm/degC and 0.05 ppm/degC^2; accelerometer 30, -25, 20 ppm/degC).
const double kScaleFactors_ppm[6] = {300 - 50 + 1.25, -200 + 40 + 1.25, 150 - 60 + 1.25,
                                     500 - 150,       -400 + 125,       300 - 100};
// Its misalignment [rad], the same for both triads (row = sensor axis, column = input axis).
const double kMisalignment_rad[3][3] = {{0.0, 2.0e-4, -1.0e-4}, {-1.5e-4, 0.0, 1.0e-4}, {1.0e-4, -2.0e-4, 0.0}};

struct CsvRows {
  std::vector<std::vector<std::string>> rows;
  static CsvRows parse(const std::string& text) {
    CsvRows table;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      std::vector<std::string> cells;
      std::istringstream fields(line);
      for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
      table.rows.push_back(cells);
    }
    return table;
  }
};

TEST(LotReport, EmulatedUnitsGiveMedianAndMaximumNearTheProfile) {
  const std::string directory = scratch_directory();
  std::string unit_directories;
  for (int seed : {1801, 1802, 1803}) {
    const std::string bag = directory + "/unit" + std::to_string(seed) + ".bag";
    const auto emulated = run_tool("emulate", "--profile tactical_mems --duration-s 900 --rate-hz 100 --seed " +
                                                  std::to_string(seed) + " --no-truth --no-increments --out " + bag);
    ASSERT_EQ(emulated.exit_code, 0) << emulated.output;
    const std::string out = directory + "/unit" + std::to_string(seed);
    const auto analysed = run_tool("allan", bag + " --no-plot --out " + out);
    ASSERT_EQ(analysed.exit_code, 0) << analysed.output;
    unit_directories += " " + out;
  }
  const std::string lot = directory + "/lot";
  const auto reported = run_tool("lot_report", unit_directories + " --out " + lot);
  ASSERT_EQ(reported.exit_code, 0) << reported.output;
  for (const char* name : {"lot.csv", "lot.yaml", "lot.md", "lot_model.csv", "lot_allan.png"}) {
    EXPECT_TRUE(file_exists(lot + "/" + name)) << name << "\n" << reported.output;
  }
  EXPECT_NE(read_file(lot + "/lot.md").find("| gyro_x | white_rate | deg_per_sqrt_h |"), std::string::npos);

  const YAML::Node summary = YAML::Load(read_file(lot + "/lot.yaml"));
  int checked = 0;
  for (const YAML::Node& term : summary["terms"]) {
    if (term["term"].as<std::string>() != "white_rate") continue;
    const bool gyro = term["channel"].as<std::string>().rfind("gyro", 0) == 0;
    EXPECT_EQ(term["parameter"].as<std::string>(), gyro ? "N_deg_per_sqrt_h" : "N_m_s_per_sqrt_h");
    ASSERT_EQ(term["identified_in"].as<int>(), 3) << term;
    std::vector<double> values;
    double largest_sigma = 0.0;
    for (const auto& unit : term["units"]) {
      values.push_back(unit.second["value"].as<double>());
      largest_sigma = std::max(largest_sigma, unit.second["sigma"].as<double>());
    }
    std::sort(values.begin(), values.end());
    const double typical = term["typical_median"].as<double>();
    EXPECT_DOUBLE_EQ(typical, values[1]) << term;
    EXPECT_DOUBLE_EQ(term["worst_max"].as<double>(), values[2]) << term;
    // The median of three estimates each within its sigma of the truth: 4 of the largest sigma
    // (one unit's estimate outside 4 sigma is a 6e-5 event; the median needs two of them).
    const double truth = gyro ? kGyroN_deg_per_sqrt_h : kAccelN_m_s_per_sqrt_h;
    EXPECT_NEAR(typical, truth, 4.0 * largest_sigma) << term;
    ++checked;
  }
  EXPECT_EQ(checked, 6);

  // A second run that fails leaves the set as it was; bad input names the option.
  const auto one = run_tool("lot_report", directory + "/unit1801 --out " + lot);
  EXPECT_EQ(one.exit_code, 2) << one.output;
  EXPECT_NE(one.output.find("units"), std::string::npos) << one.output;
  const auto names = run_tool("lot_report", unit_directories + " --names a b --out " + lot);
  EXPECT_EQ(names.exit_code, 2) << names.output;
  EXPECT_NE(names.output.find("--names"), std::string::npos) << names.output;
  const auto missing = run_tool("lot_report", unit_directories + " " + directory + " --out " + lot);
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_NE(missing.output.find(directory + "/noise.yaml"), std::string::npos) << missing.output;
  EXPECT_TRUE(file_exists(lot + "/lot_allan.png"));
}

TEST(LotReport, RepeatabilityOfEmulatedCalibrations) {
  const std::string directory = scratch_directory();
  const std::string schedule = write_quick_twelve_position_schedule(directory);
  std::vector<std::string> calibrations;
  for (int seed : {1811, 1812, 1813, 1814}) {
    const std::string bag = directory + "/calibration" + std::to_string(seed) + ".bag";
    const auto emulated = run_tool("emulate", "--profile tactical_mems --scenario " + schedule +
                                                  " --rate-hz 100 --seed " + std::to_string(seed) + " --out " + bag);
    ASSERT_EQ(emulated.exit_code, 0) << emulated.output;
    calibrations.push_back(directory + "/calibration" + std::to_string(seed) + ".yaml");
    const auto fitted = run_tool("fit_calibration", bag + " --schedule " + schedule + " --out " + calibrations.back());
    ASSERT_EQ(fitted.exit_code, 0) << fitted.output;
  }
  std::string arguments = "--calibrations";
  for (const std::string& path : calibrations) arguments += " " + path;
  const auto result = run_tool("repeatability", arguments + " --out " + directory + "/repeatability");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const CsvRows table = CsvRows::parse(read_file(directory + "/repeatability/calibration_repeatability.csv"));

  // The files' own scale factors, gyro x..z then accelerometer x..z.
  std::vector<std::vector<double>> files(6);
  for (const std::string& path : calibrations) {
    const auto calibration = imu_lab::calib::load_calibration(path);
    for (int i = 0; i < 3; ++i) {
      files[i].push_back(calibration.gyro.scale_factor_error_ppm()[i]);
      files[3 + i].push_back(calibration.accelerometer.scale_factor_error_ppm()[i]);
    }
  }
  int scale_factor_rows = 0, misalignment_rows = 0;
  for (const auto& row : table.rows) {
    if (row.size() != 8 || row[0] == "parameter") continue;
    EXPECT_EQ(row[2], "4") << row[0];
    const double mean = std::stod(row[3]), deviation = std::stod(row[4]);
    EXPECT_TRUE(std::isfinite(deviation) && deviation > 0.0) << row[0];
    EXPECT_LE(std::stod(row[5]), deviation);
    EXPECT_GE(std::stod(row[6]), deviation);
    // The mean of 4 within 5 standard errors of the profile's value (t with 3 degrees of
    // freedom: beyond 5 in 1.5 % of cases per parameter).
    const double tolerance = 5.0 * deviation / 2.0;
    if (row[0].find("_misalignment_") != std::string::npos) {
      EXPECT_EQ(row[1], "arcsec");
      const int i = row[0][row[0].size() - 2] - 'x', j = row[0].back() - 'x';
      EXPECT_NEAR(mean, kMisalignment_rad[i][j] / units::kArcsecond_rad, tolerance) << row[0];
      ++misalignment_rows;
      continue;
    }
    ASSERT_EQ(row[1], "ppm") << row[0];
    const int index = (row[0].rfind("accel", 0) == 0 ? 3 : 0) + (row[0].back() - 'x');
    double sum = 0.0, squares = 0.0;
    for (double value : files[index]) sum += value;
    for (double value : files[index]) squares += (value - sum / 4.0) * (value - sum / 4.0);
    EXPECT_NEAR(mean, sum / 4.0, 1e-6 * std::abs(sum)) << row[0];
    EXPECT_NEAR(deviation, std::sqrt(squares / 3.0), 1e-6 * deviation) << row[0];
    EXPECT_NEAR(mean, kScaleFactors_ppm[index], tolerance) << row[0];
    ++scale_factor_rows;
  }
  EXPECT_EQ(scale_factor_rows, 6);
  EXPECT_EQ(misalignment_rows, 12);
}

}  // namespace
