// The spectrum tool, run as a user runs it, on a bag from the emulate tool: a white-noise profile
// whose gyro axes are correlated by noise.white_rate.axis_correlation. Every file written; the
// estimated correlation matrix holds the profile's matrix inside its interval at tau0 and after
// averaging (the accelerometer's, independent, holds the identity); the PSD is the white density
// 2 N^2 (one-sided); `--model` draws the noise `allan` identifies over it. Bad options exit 2
// naming the option, a record too short for what is asked (or a missing model) exits 1 naming it,
// and neither writes anything.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "imu_lab/ros_io/node/config_paths.h"
#include "ros_test_support.h"

namespace {

using imu_lab::test_support::file_exists;
using imu_lab::test_support::list_directory;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;

constexpr double kGyroDensity = 1e-3;  // rad/s/sqrt(Hz)
constexpr double kCorrelation[3][3] = {{1.0, 0.5, -0.2}, {0.5, 1.0, 0.1}, {-0.2, 0.1, 1.0}};

// Emulated once for the whole file.
const std::string& correlated_bag() {
  static const std::string bag = [] {
    const std::string directory = scratch_directory();
    // The ideal profile with white noise only: the gyro's axes correlated, the accelerometer's not.
    YAML::Node root = YAML::LoadFile(imu_lab::ros_io::resolve_config("sensors", "ideal"));
    root["name"] = "correlated";
    root["gyro"]["noise"] = YAML::Load(
        "{white_rate: {density_rad_s_per_sqrt_hz: 1.0e-3, "
        "axis_correlation: [[1, 0.5, -0.2], [0.5, 1, 0.1], [-0.2, 0.1, 1]]}}");
    root["accelerometer"]["noise"] = YAML::Load("{white_rate: {density_m_s2_per_sqrt_hz: 1.0e-3}}");
    const std::string profile = directory + "/correlated.yaml", path = directory + "/static.bag";
    std::ofstream(profile) << YAML::Dump(root) << "\n";
    const auto result = run_tool("emulate", "--profile " + profile +
                                                " --scenario static --duration-s 300 "
                                                "--rate-hz 100 --seed 5 --no-truth --no-increments --out " +
                                                path);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return path;
  }();
  return bag;
}

TEST(SpectrumTool, WritesEveryFileAndFindsTheProfilesCorrelation) {
  const std::string out = scratch_directory() + "/report";
  // 99.9 %: each of the 18 intervals checked below misses the truth once in 1000 runs.
  const auto result = run_tool("spectrum", correlated_bag() + " --confidence 0.999 --out " + out);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("30000 samples, tau0 0.01 s; Welch: 13 segments of 4096"), std::string::npos)
      << result.output;
  ASSERT_TRUE(file_exists(out + "/spectrum_psd.csv"));
  ASSERT_TRUE(file_exists(out + "/spectrum_autocorrelation.csv"));
  if (file_exists("/usr/bin/python3")) {
    EXPECT_TRUE(file_exists(out + "/spectrum.png")) << result.output;
  }
  const YAML::Node report = YAML::LoadFile(out + "/spectrum.yaml");
  EXPECT_EQ(report["welch"]["segment_count"].as<int>(), 13);
  for (const char* triad : {"gyro", "accelerometer"}) {
    const YAML::Node by_factor = report["axis_correlation"][triad];
    ASSERT_EQ(by_factor.size(), 3u) << triad;
    for (const YAML::Node& c : by_factor) {
      for (int a = 0; a < 3; ++a) {
        for (int b2 = a + 1; b2 < 3; ++b2) {
          const double truth = std::string(triad) == "gyro" ? kCorrelation[a][b2] : 0.0;
          EXPECT_LE(c["lower"][a][b2].as<double>(), truth) << triad << " m " << c["averaging_factor"] << " " << a << b2;
          EXPECT_GE(c["upper"][a][b2].as<double>(), truth) << triad << " m " << c["averaging_factor"] << " " << a << b2;
        }
      }
    }
  }
  // Mean of the gyro x density over bins 1 .. 2046: white noise's one-sided 2 N^2. Each bin is
  // chi2(nu)/nu, neighbours correlated, so the mean's relative sigma is at most
  // sqrt(2 / (nu x 1023)); 5 sigma.
  std::ifstream csv(out + "/spectrum_psd.csv");
  std::string line;
  std::getline(csv, line);
  ASSERT_EQ(line.rfind("frequency_hz,degrees_of_freedom,gyro_x_psd_rad2_s2_per_hz,", 0), 0u) << line;
  double sum = 0.0, nu = 0.0;
  int bins = 0;
  while (std::getline(csv, line)) {
    std::stringstream fields(line);
    std::string frequency, dof, density;
    std::getline(fields, frequency, ',');
    std::getline(fields, dof, ',');
    std::getline(fields, density, ',');
    if (bins > 0 && std::stod(dof) != nu) break;  // Nyquist, the last bin, has half the degrees of freedom
    nu = std::stod(dof);
    sum += std::stod(density);
    ++bins;
  }
  ASSERT_EQ(bins, 2047);
  const double expected = 2.0 * kGyroDensity * kGyroDensity;
  EXPECT_NEAR(sum / bins / expected, 1.0, 5.0 * std::sqrt(2.0 / (nu * bins / 2.0)));
}

// `allan` identifies the bag's noise, `spectrum --model` draws it: every channel gets a model
// column, the plot is written, and over bins 1 .. 2046 the estimate's mean over the model's is 1
// within 5 sigma of the estimate's mean (as above) and of the identified N (its sigma in noise.yaml,
// doubled for N^2).
TEST(SpectrumTool, DrawsTheIdentifiedModel) {
  const std::string allan_out = scratch_directory() + "/allan", out = scratch_directory() + "/report";
  const auto identified = run_tool("allan", correlated_bag() + " -o " + allan_out);
  ASSERT_EQ(identified.exit_code, 0) << identified.output;
  const auto result = run_tool("spectrum", correlated_bag() + " --model " + allan_out + "/noise.yaml --out " + out);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("gyro_x model drawn: estimate / model median"), std::string::npos) << result.output;
  if (file_exists("/usr/bin/python3")) {
    EXPECT_TRUE(file_exists(out + "/spectrum.png")) << result.output;
  }
  const YAML::Node noise = YAML::LoadFile(allan_out + "/noise.yaml");
  const YAML::Node white = noise["triads"]["gyro"]["axes"]["gyro_x"]["terms"]["white_rate"];
  const double n_relative_sigma =
      white["N_rad_s_per_sqrt_hz_sigma"].as<double>() / white["N_rad_s_per_sqrt_hz"].as<double>();

  std::ifstream csv(out + "/spectrum_psd.csv");
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> header;
  std::stringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  std::size_t estimate_column = 0, model_column = 0;
  int model_columns = 0;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == "gyro_x_psd_rad2_s2_per_hz") estimate_column = i;
    if (header[i] == "gyro_x_model_psd_rad2_s2_per_hz") model_column = i;
    model_columns += header[i].find("_model_psd_") != std::string::npos ? 1 : 0;
  }
  EXPECT_EQ(model_columns, 6) << line;
  ASSERT_GT(model_column, estimate_column) << line;
  double estimate_sum = 0.0, model_sum = 0.0, nu = 0.0;
  int bins = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    if (bins > 0 && std::stod(fields[1]) != nu) break;  // Nyquist
    nu = std::stod(fields[1]);
    estimate_sum += std::stod(fields[estimate_column]);
    model_sum += std::stod(fields[model_column]);
    ++bins;
  }
  ASSERT_EQ(bins, 2047);
  const double sigma = std::hypot(std::sqrt(2.0 / (nu * bins / 2.0)), 2.0 * n_relative_sigma);
  EXPECT_NEAR(estimate_sum / model_sum, 1.0, 5.0 * sigma) << "N relative sigma " << n_relative_sigma;
}

TEST(SpectrumTool, BadOptionsExitTwoAndTooShortARecordExitsOneNamingIt) {
  const std::string& bag = correlated_bag();
  const std::string out = scratch_directory();
  struct Case {
    std::string arguments;
    int exit_code;
    std::vector<std::string> words;
  };
  const std::vector<Case> cases = {
      {"--averaging-factors 0", 2, {"--averaging-factors"}},
      {"--confidence 1", 2, {"--confidence"}},
      {"--averaging-factors 1 5000 --no-plot", 1, {bag, "averaging factor 5000 leaves 6 blocks"}},
      {"--model /nonexistent/noise.yaml --no-plot", 1, {"cannot read noise report /nonexistent/noise.yaml"}},
      {"--segment-length 65536 --no-plot",
       1,
       {bag, "gyro_x: Welch PSD: 30000 samples, fewer than one segment of 65536"}},
  };
  for (const Case& c : cases) {
    const auto result = run_tool("spectrum", bag + " " + c.arguments + " --out " + out + "/r");
    EXPECT_EQ(result.exit_code, c.exit_code) << c.arguments << "\n" << result.output;
    for (const std::string& word : c.words) {
      EXPECT_NE(result.output.find(word), std::string::npos) << c.arguments << ": no '" << word << "' in\n"
                                                             << result.output;
    }
  }
  EXPECT_TRUE(list_directory(out).empty());
}

}  // namespace
