// The allan tool's noise identification, run as a user runs it on an emulated bag whose noise is
// known (white rate + rate random walk, 20 min at 50 Hz): the Kalibr density agrees with the
// profile within the fit's own 3 sigma, the partial curves add up to the fitted total, and
// --no-identify or a refused fit leave the Allan curves alone. And a zero-at-DC term, enabled with
// --zero-dc-terms, found with its parameters on a bag that has one.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "imu_lab/identify/noise_report.h"
#include "allan_test_support.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::file_exists;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;

constexpr double kGyroWhite_rad_s_per_sqrt_hz = 1.0e-3;
constexpr double kGyroWalk_rad_s_per_sqrt_s = 2.0e-5;  // crosses the white noise at tau ~ 90 s

// A profile with no bias, scale-factor or misalignment error and the given noise blocks (YAML
// lines, each indented four spaces) per triad.
std::string noise_only_profile(const std::string& name, const std::string& gyro_noise,
                               const std::string& accelerometer_noise) {
  std::ostringstream profile;
  const char* const zero_matrix = "[[0, 0, 0], [0, 0, 0], [0, 0, 0]]";
  profile << "name: " << name << "\n";
  profile << "gyro:\n  bias_fixed_rad_s: 0.0\n  bias_turn_on_sigma_rad_s: 0.0\n  scale_factor_error_ppm: 0.0\n"
          << "  misalignment_rad: " << zero_matrix << "\n  noise:\n"
          << gyro_noise;
  profile << "accelerometer:\n  bias_fixed_m_s2: 0.0\n  bias_turn_on_sigma_m_s2: 0.0\n  scale_factor_error_ppm: 0.0\n"
          << "  misalignment_rad: " << zero_matrix << "\n  noise:\n"
          << accelerometer_noise;
  return profile.str();
}

std::string white_and_walk_profile() {
  std::ostringstream gyro;
  gyro << "    white_rate: {density_rad_s_per_sqrt_hz: " << kGyroWhite_rad_s_per_sqrt_hz << "}\n"
       << "    random_walk: {density_rad_s_per_sqrt_s: " << kGyroWalk_rad_s_per_sqrt_s << "}\n";
  return noise_only_profile("white_and_walk", gyro.str(),
                            "    white_rate: {density_m_s2_per_sqrt_hz: 2.0e-3}\n"
                            "    random_walk: {density_m_s2_per_sqrt_s: 5.0e-5}\n");
}

class AllanNoiseReport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = scratch_directory();
    const std::string profile = directory_ + "/white_and_walk.yaml";
    std::ofstream(profile) << white_and_walk_profile();
    bag_ = directory_ + "/white_and_walk.bag";
    const auto made = run_tool("emulate", "--profile " + profile +
                                              " --duration-s 1200 --rate-hz 50 --seed 11 "
                                              "--no-truth --out " +
                                              bag_);
    ASSERT_EQ(made.exit_code, 0) << made.output;
    report_ = directory_ + "/report";
    const auto run = run_tool("allan", bag_ + " --topic /imu/raw --no-plot --out " + report_);
    output_ = run.output;
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }

  static std::string directory_;
  static std::string bag_;
  static std::string report_;
  static std::string output_;
};

std::string AllanNoiseReport::directory_;
std::string AllanNoiseReport::bag_;
std::string AllanNoiseReport::report_;
std::string AllanNoiseReport::output_;

TEST_F(AllanNoiseReport, KalibrDensityIsTheProfilesWithinThreeSigmaOfTheFit) {
  ASSERT_TRUE(file_exists(report_ + "/noise.yaml")) << output_;
  ASSERT_TRUE(file_exists(report_ + "/kalibr_imu.yaml")) << output_;
  const auto values = imu_lab::identify::read_noise_report_values(read_file(report_ + "/noise.yaml"));
  const YAML::Node kalibr = YAML::LoadFile(report_ + "/kalibr_imu.yaml");
  const double density = kalibr["gyroscope_noise_density"].as<double>();
  EXPECT_NEAR(kalibr["update_rate"].as<double>(), 50.0, 1e-6);
  EXPECT_EQ(kalibr["rostopic"].as<std::string>(), "/imu/raw");
  // Kalibr takes the largest axis (printed to 6 digits); its sigma is that axis's.
  double sigma = 0.0;
  for (const char* axis : {"gyro_x", "gyro_y", "gyro_z"}) {
    const std::string key = std::string("triads.gyro.axes.") + axis + ".terms.white_rate.N_rad_s_per_sqrt_hz";
    ASSERT_EQ(values.count(key), 1u) << key;
    if (std::abs(values.at(key) - density) < 1e-5 * density) sigma = values.at(key + "_sigma");
  }
  ASSERT_GT(sigma, 0.0) << "no gyro axis has the Kalibr density";
  EXPECT_NEAR(density, kGyroWhite_rad_s_per_sqrt_hz, 3.0 * sigma);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

// What a VIO user came for leads the output: Kalibr's four numbers as kalibr_imu.yaml has them,
// then one row per axis of the IEEE terms; the files in one line; the topic to set.
TEST_F(AllanNoiseReport, TheConsoleLeadsWithTheKalibrNumbersAndOneRowPerAxis) {
  const std::vector<std::string> lines = lines_of(output_);
  ASSERT_GE(lines.size(), 5u) << output_;
  EXPECT_EQ(lines[0].rfind("allan: Kalibr / OpenVINS noise model", 0), 0u) << output_;
  const YAML::Node kalibr = YAML::LoadFile(report_ + "/kalibr_imu.yaml");
  const char* const keys[] = {"gyroscope_noise_density", "gyroscope_random_walk", "accelerometer_noise_density",
                              "accelerometer_random_walk"};
  for (int i = 0; i < 4; ++i) {
    std::istringstream line(lines[1 + i]);
    std::string key;
    double value = 0.0;
    line >> key >> value;
    EXPECT_EQ(key, keys[i]) << output_;
    EXPECT_NEAR(value, kalibr[keys[i]].as<double>(), 5e-4 * value) << lines[1 + i];  // 4 digits
  }
  for (const char* axis : {"gyro_x", "gyro_y", "gyro_z", "accel_x", "accel_y", "accel_z"}) {
    std::size_t rows = 0;
    for (const std::string& line : lines) rows += line.rfind(std::string("  ") + axis + " ", 0) == 0 ? 1 : 0;
    EXPECT_EQ(rows, 1u) << axis << "\n" << output_;
  }
  EXPECT_NE(output_.find("K [deg_h_per_sqrt_h]"), std::string::npos) << output_;
  std::size_t wrote = 0;
  for (const std::string& line : lines) wrote += line.rfind("allan: wrote ", 0) == 0 ? 1 : 0;
  EXPECT_EQ(wrote, 1u) << output_;
  EXPECT_NE(output_.find("allan: wrote " + report_ + "/: "), std::string::npos) << output_;
  EXPECT_NE(output_.find(" kalibr_imu_chain.yaml"), std::string::npos) << output_;
  EXPECT_NE(output_.find("hold rostopic /imu/raw, the recording's: set it to the topic your IMU publishes on"),
            std::string::npos)
      << output_;
  // The estimator's vocabulary stays in noise.yaml and --verbose.
  for (const char* jargon : {"moment_covariance", "Akaike", "q_c_T_c", "worst gyro axis"})
    EXPECT_EQ(output_.find(jargon), std::string::npos) << jargon << "\n" << output_;
}

TEST_F(AllanNoiseReport, VerbosePrintsTheFullTableAndEveryWarning) {
  const std::string report = scratch_directory() + "/report";
  const auto run = run_tool("allan", bag_ + " --topic /imu/raw --no-plot --verbose --out " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("worst gyro axis"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("(moment_covariance)"), std::string::npos) << run.output;
  const YAML::Node noise = YAML::LoadFile(report + "/noise.yaml");
  for (const char* triad : {"gyro", "accel"}) {
    for (const auto& axis : noise["triads"][triad]["axes"]) {
      for (const auto& warning : axis.second["warnings"]) {
        EXPECT_NE(run.output.find(warning.as<std::string>()), std::string::npos) << warning.as<std::string>();
      }
    }
  }
}

// OpenVINS's file beside Kalibr's, with the same numbers under imu0.
TEST_F(AllanNoiseReport, TheOpenVinsFileHasKalibrsNumbersUnderImu0) {
  const std::string path = report_ + "/kalibr_imu_chain.yaml";
  ASSERT_TRUE(file_exists(path)) << output_;
  const std::string text = read_file(path);
  const YAML::Node chain = YAML::Load(text.substr(text.find('\n') + 1));  // after OpenCV's %YAML:1.0
  const YAML::Node kalibr = YAML::LoadFile(report_ + "/kalibr_imu.yaml");
  for (const char* key : {"gyroscope_noise_density", "gyroscope_random_walk", "accelerometer_noise_density",
                          "accelerometer_random_walk", "update_rate"}) {
    EXPECT_EQ(chain["imu0"][key].as<double>(), kalibr[key].as<double>()) << key;
  }
  EXPECT_EQ(chain["imu0"]["rostopic"].as<std::string>(), "/imu/raw");
  const std::string no_identify = scratch_directory() + "/report";
  const auto run = run_tool("allan", bag_ + " --no-plot --no-identify --out " + no_identify);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_FALSE(file_exists(no_identify + "/kalibr_imu_chain.yaml"));
  EXPECT_EQ(run.output.find("rostopic"), std::string::npos) << run.output;
}

TEST_F(AllanNoiseReport, PartialCurvesAddUpToTheFittedTotal) {
  for (const char* channel : {"gyro_x", "gyro_y", "gyro_z", "accel_x", "accel_y", "accel_z"}) {
    const std::string path = report_ + "/noise_partial_" + channel + ".csv";
    ASSERT_TRUE(file_exists(path)) << path;
    const imu_lab::test_support::CsvTable table = imu_lab::test_support::read_csv_table(path);
    const auto& header = table.header;
    const auto& rows = table.rows;
    ASSERT_GE(header.size(), 5u) << path << ": white_rate and random_walk at least";
    ASSERT_GT(rows.size(), 10u) << path;
    for (const auto& row : rows) {
      ASSERT_EQ(row.size(), header.size()) << path;
      double variance_sum = 0.0;  // the terms' variances add, not their deviations
      for (std::size_t term = 3; term < row.size(); ++term) {
        // Term columns are "<term>_dev_<unit>"; the band's two columns follow them.
        if (header[term].find("_dev_") != std::string::npos) variance_sum += row[term] * row[term];
      }
      EXPECT_NEAR(std::sqrt(variance_sum), row[2], 1e-9 * row[2]) << path << " tau " << row[0];
    }
  }
}

TEST_F(AllanNoiseReport, SummarySaysWhatWasIdentified) {
  const YAML::Node summary = YAML::LoadFile(report_ + "/allan_summary.yaml");
  EXPECT_EQ(summary["identification"]["sigma_source"].as<std::string>(), "moment_covariance");
  EXPECT_EQ(summary["identification"]["identified"].size(), 2u);
  EXPECT_EQ(summary["identification"]["problems"].size(), 0u);
}

TEST_F(AllanNoiseReport, NoIdentifyWritesNeitherNoiseFile) {
  const std::string report = scratch_directory() + "/report";
  const auto run = run_tool("allan", bag_ + " --no-plot --no-identify --out " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(file_exists(report + "/oadev.csv"));
  EXPECT_FALSE(file_exists(report + "/noise.yaml"));
  EXPECT_FALSE(file_exists(report + "/kalibr_imu.yaml"));
  EXPECT_FALSE(file_exists(report + "/noise_partial_gyro_x.csv"));
}

TEST_F(AllanNoiseReport, ARefusedFitKeepsTheCurvesAndSaysTheRecordIsTooShort) {
  // Curves that stop at 0.05 s: fewer than three octave points for the fit.
  const std::string report = scratch_directory() + "/report";
  const auto run = run_tool("allan", bag_ + " --no-plot --max-tau-s 0.05 --out " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(file_exists(report + "/oadev.csv"));
  EXPECT_FALSE(file_exists(report + "/noise.yaml"));
  EXPECT_NE(run.output.find("record too short"), std::string::npos) << run.output;
  const YAML::Node summary = YAML::LoadFile(report + "/allan_summary.yaml");
  EXPECT_EQ(summary["identification"]["problems"].size(), 2u);  // gyro and accel
  EXPECT_EQ(summary["identification"]["identified"].size(), 0u);
}

// Gyros: white noise 1e-3 behind a 0.5 Hz high-pass (table 7.3) over a white floor of 1e-4;
// accelerometers: alpha f^2 exp(-beta f^2) (table 7.1 row 2), its peak at 1 / sqrt(beta) = 5 Hz
// about 20x the white floor's PSD. Each parameter of each axis within 3 of its reported sigmas
// of the truth (12 zero-at-DC values and 6 N: at honest sigmas each misses with p = 0.0027).
TEST(AllanNoiseReportZeroDc, EnabledTermsAreFoundWithTheirParameters) {
  const std::string directory = scratch_directory();
  const std::string profile = directory + "/zero_dc.yaml", bag = directory + "/zero_dc.bag";
  std::ofstream(profile) << noise_only_profile(
      "zero_dc",
      "    white_rate: {density_rad_s_per_sqrt_hz: 1.0e-4}\n"
      "    high_pass_white: {density_rad_s_per_sqrt_hz: 1.0e-3, corner_frequency_hz: 0.5}\n",
      "    white_rate: {density_m_s2_per_sqrt_hz: 2.0e-3}\n"
      "    zero_dc_gaussian: {exponent_n: 2, alpha_m2_s4_per_hz_n_plus_1: 1.0e-5, beta_s2: 0.04}\n");
  const auto made =
      run_tool("emulate", "--profile " + profile + " --duration-s 1200 --rate-hz 50 --seed 21 --no-truth --out " + bag);
  ASSERT_EQ(made.exit_code, 0) << made.output;
  const std::string report = directory + "/report";
  const auto run =
      run_tool("allan", bag + " --no-plot --zero-dc-terms high_pass_white,zero_dc_gaussian --out " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto values = imu_lab::identify::read_noise_report_values(read_file(report + "/noise.yaml"));
  const auto expect_within_3_sigma = [&](const std::string& key, double truth) {
    ASSERT_TRUE(values.count(key) && values.count(key + "_sigma")) << key << " missing\n" << run.output;
    EXPECT_NEAR(values.at(key), truth, 3.0 * values.at(key + "_sigma")) << key;
  };
  for (const char* axis : {"gyro_x", "gyro_y", "gyro_z"}) {
    const std::string terms = std::string("triads.gyro.axes.") + axis + ".terms.";
    expect_within_3_sigma(terms + "high_pass_white.sqrt_alpha_rad_s_per_sqrt_hz", 1.0e-3);
    expect_within_3_sigma(terms + "high_pass_white.beta_hz", 0.5);
    expect_within_3_sigma(terms + "white_rate.N_rad_s_per_sqrt_hz", 1.0e-4);
  }
  for (const char* axis : {"accel_x", "accel_y", "accel_z"}) {
    const std::string terms = std::string("triads.accel.axes.") + axis + ".terms.";
    expect_within_3_sigma(terms + "zero_dc_gaussian.sqrt_alpha_m_s2_per_hz_1_5", std::sqrt(1.0e-5));
    expect_within_3_sigma(terms + "zero_dc_gaussian.beta_s2", 0.04);
    expect_within_3_sigma(terms + "white_rate.N_m_s2_per_sqrt_hz", 2.0e-3);
  }

  // Without the option neither term can enter.
  const std::string plain = directory + "/plain";
  const auto default_run = run_tool("allan", bag + " --no-plot --out " + plain);
  ASSERT_EQ(default_run.exit_code, 0) << default_run.output;
  const std::string noise = read_file(plain + "/noise.yaml");
  EXPECT_EQ(noise.find("high_pass_white"), std::string::npos);
  EXPECT_EQ(noise.find("zero_dc_gaussian"), std::string::npos);
}

}  // namespace
