// The tools at the edges (issue 16's matrix), run as a user runs them: option errors exit 2 with
// the option named; numbers that cannot be right are refused; a bag that cannot be written (disk
// full) is refused with the file and the cause, the old one kept; a set of outputs with one path
// blocked stays the whole old set; a triad marked as not provided (covariance[0] = -1) is left
// out or refused, never processed as zeros; values beyond +-1e100 are left out (allan) or refused;
// every refusal names the bag; the package's files are found without a sourced workspace.
#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "allan_test_support.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "ros_test_support.h"

namespace {

using namespace imu_lab::test_support;  // NOLINT: the scratch, bag and tool helpers

constexpr std::int64_t kInterval_ns = 10'000'000;  // 100 Hz
const std::string kData = IMU_LAB_TEST_DATA_DIR;

using imu_lab::test_support::contains;

using FileContents = std::map<std::string, std::string>;  // name -> bytes

// The regular files in a directory (sub-directories are listed by name only).
FileContents contents_of(const std::string& directory) {
  FileContents files;
  for (const std::string& name : list_directory(directory)) {
    struct stat status {};
    ::stat((directory + "/" + name).c_str(), &status);
    files[name] = S_ISDIR(status.st_mode) ? "(directory)" : read_file(directory + "/" + name);
  }
  return files;
}

// A directory with a file in it where an output file should go: no rename can replace it.
void block(const std::string& path) {
  std::remove(path.c_str());
  ASSERT_EQ(::mkdir(path.c_str(), 0755), 0) << path;
  std::ofstream(path + "/blocker") << "x";
}

std::string white_noise_bag(const std::string& path, unsigned seed, const ImuBagLayout& layout = ImuBagLayout(),
                            std::size_t count = 3000) {
  write_imu_bag(path, white_noise_samples(count, kInterval_ns, seed), layout);
  return path;
}

ImuBagLayout with_temperature() {
  ImuBagLayout layout;
  layout.with_temperature = true;
  return layout;
}

// ---- Options ----

const std::vector<std::string> kTools = {"allan",           "bag_summary", "correct",    "emulate",  "export_csv",
                                         "fit_calibration", "fit_thermal", "import_csv", "navigate", "rate_table",
                                         "repeatability",   "lot_report",  "spectrum"};

// CLI11's own codes were 105-114 (navigate with no arguments: 106); the tools document 2.
TEST(ToolOptionErrors, EveryToolExitsTwoNamingTheProblem) {
  for (const std::string& tool : kTools) {
    const CommandResult none = run_tool(tool, "");
    EXPECT_EQ(none.exit_code, 2) << tool << ":\n" << none.output;
    EXPECT_TRUE(contains(none.output, tool + ": bad configuration: ")) << none.output;
    const CommandResult unknown = run_tool(tool, "some.input --out x --no-such-option");
    EXPECT_EQ(unknown.exit_code, 2) << tool << ":\n" << unknown.output;
    EXPECT_TRUE(contains(unknown.output, "--no-such-option")) << unknown.output;
    EXPECT_EQ(run_tool(tool, "--help").exit_code, 0) << tool;
  }
}

// Numbers that cannot be right used to run (exit 0) or fall back to a default silently.
TEST(ToolNumericOptions, NonsenseNumbersAreRefusedNamingTheOptionAndWriteNothing) {
  const std::string outputs = scratch_directory();
  const std::string bag = white_noise_bag(scratch_directory() + "/good.bag", 1, with_temperature());
  const std::string out = " --out " + outputs + "/out";
  struct Case {
    std::string tool, arguments, words;
  };
  const std::vector<Case> cases = {
      {"emulate", "--duration-s -5" + out, "--duration-s: must be > 0, got -5"},
      {"emulate", "--duration-s 0" + out, "--duration-s: must be > 0"},
      {"emulate", "--duration-s nan" + out, "--duration-s: 'nan' is not a finite number"},
      {"emulate", "--duration-s 10 --rate-hz 1e-300" + out, "holds no sample"},
      {"emulate", "--duration-s 10 --rate-hz 2e9" + out, "--rate-hz: must be in [0, 1e+09]"},
      {"emulate", "--duration-s 1 --start-time-s 1e20" + out, "beyond ROS time"},
      {"emulate", "--duration-s 1e400" + out, "--duration-s: '1e400' is not a finite number"},
      {"emulate", "--seed -1" + out, "--seed: must not be negative"},
      {"navigate", bag + " --every-s nan" + out, "--every-s: 'nan' is not a finite number"},
      {"navigate", bag + " --every-s -1" + out, "--every-s: must be >= 0"},
      {"navigate", bag + " --latitude-deg 50 --longitude-deg 30 --height-m 1e12" + out,
       "height_m: must be in [-11000, 100000] m"},
      {"navigate", bag + " --latitude-deg 50 --longitude-deg 1e6 --height-m 0" + out,
       "longitude_deg: must be in [-180, 360] degrees"},
      {"navigate",
       bag +
           " --latitude-deg 50 --longitude-deg 30 --height-m 0 --no-align --initial-velocity-enu-m-s 0,0,0"
           " --initial-yaw-deg 1e300" +
           out,
       "initial_yaw_deg: must be in [-360, 360]"},
      {"import_csv", "x.csv --time-offset-s -1e30" + out, "--time-offset-s: '-1e30' is not a number of seconds within"},
      {"fit_thermal", bag + " --latitude-deg 95" + out, "--latitude-deg: must be in [-90, 90], got 95"},
      {"fit_calibration", bag + " --latitude-deg 95 --height-m 0" + out, "--latitude-deg: must be in [-90, 90]"},
      {"fit_calibration", bag + " --latitude-deg 50 --height-m 1e9" + out, "--height-m"},
      {"bag_summary", bag + " --taus-s -1", "--taus-s: must be > 0, got -1"},
      {"allan", bag + " --gap-factor nan" + out, "--gap-factor: 'nan' is not a finite number"},
      {"correct", bag + " --calibration " + kData + "/calibration_example.yaml --max-temperature-age-s inf" + out,
       "--max-temperature-age-s: 'inf' is not a finite number"},
      {"import_csv", "x.csv --max-reported-rows -1" + out, "--max-reported-rows: must not be negative"},
      {"lot_report", "unit_a unit_b --confidence 1.5" + out, "--confidence: must be between 0 and 1"},
      {"lot_report", "unit_a unit_b --confidence nan" + out, "--confidence"},
      {"lot_report", "a/unit b/unit" + out, "two units are named unit"},
  };
  for (const Case& c : cases) {
    const CommandResult result = run_tool(c.tool, c.arguments);
    EXPECT_EQ(result.exit_code, 2) << c.tool << " " << c.arguments << "\n" << result.output;
    EXPECT_TRUE(contains(result.output, c.words)) << c.tool << ": no '" << c.words << "' in\n" << result.output;
  }
  EXPECT_EQ(list_directory(outputs), std::vector<std::string>{}) << "a refused run wrote something";
}

// ---- Disk full ----

// ulimit -f makes writes past the limit fail (EFBIG) as a full disk makes them fail (ENOSPC);
// SIGXFSZ is ignored so that the write returns the error instead of killing the tool.
CommandResult run_with_file_size_limit(const std::string& tool, const std::string& arguments) {
  return run_command("ulimit -f 200; trap '' XFSZ; " + tool_path(tool) + " " + arguments);
}

void expect_bag_refused_and_old_kept(const std::string& tool, const std::string& arguments, const std::string& out,
                                     const std::string& old_bytes) {
  const CommandResult result = run_with_file_size_limit(tool, arguments);
  EXPECT_EQ(result.exit_code, 1) << tool << ": " << result.output;  // was SIGABRT (rosbag threw from a destructor)
  EXPECT_TRUE(contains(result.output, tool + ": cannot write bag " + out)) << result.output;
  EXPECT_TRUE(contains(result.output, "File too large")) << "the cause: " << result.output;
  EXPECT_EQ(read_file(out), old_bytes) << tool << " did not keep the old bag";
  const std::string directory = out.substr(0, out.rfind('/'));
  EXPECT_EQ(list_directory(directory), std::vector<std::string>{"out.bag"}) << tool << " left a temporary";
}

TEST(ToolsDiskFull, ABagThatCannotBeWrittenIsRefusedNamingItAndTheOldOneIsKept) {
  const std::string inputs = scratch_directory();
  const std::string outputs = scratch_directory();
  const std::string out = outputs + "/out.bag";
  // The old bag: a small one, under the limit.
  ASSERT_EQ(run_tool("emulate", "--duration-s 1 --rate-hz 10 --out " + out).exit_code, 0);
  const std::string old_bytes = read_file(out);

  expect_bag_refused_and_old_kept("emulate", "--duration-s 60 --rate-hz 200 --out " + out, out, old_bytes);

  const std::string csv = inputs + "/log.csv";
  {
    std::ofstream text(csv);
    text << "time_s,gx,gy,gz,ax,ay,az\n";
    for (int i = 1; i <= 20000; ++i) text << "1700000000." << 100000 + 5 * i << ",0.001,0.002,0.003,0.1,0.2,9.8\n";
  }
  expect_bag_refused_and_old_kept("import_csv", csv + " --out " + out, out, old_bytes);

  const std::string big = inputs + "/big.bag";
  ASSERT_EQ(run_tool("emulate", "--duration-s 60 --rate-hz 200 --out " + big).exit_code, 0);
  expect_bag_refused_and_old_kept(
      "correct", big + " --topic /imu/raw --calibration " + kData + "/calibration_example.yaml --out " + out, out,
      old_bytes);
}

// ---- Sets of outputs ----

// Runs `tool` once to make the old set, blocks the output `blocked` (written after others), runs
// it on another input: it must fail naming the blocked path and leave every old file as it was.
void expect_old_set_kept(const std::string& tool, const std::string& first_arguments,
                         const std::string& second_arguments, const std::string& directory,
                         const std::string& blocked) {
  const CommandResult first = run_tool(tool, first_arguments);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  block(directory + "/" + blocked);
  const FileContents old_set = contents_of(directory);
  const CommandResult second = run_tool(tool, second_arguments);
  EXPECT_EQ(second.exit_code, 1) << second.output;
  EXPECT_TRUE(contains(second.output, directory + "/" + blocked)) << second.output;
  const FileContents after = contents_of(directory);
  EXPECT_EQ(after.size(), old_set.size()) << tool << " added or removed files";
  for (const auto& [name, bytes] : old_set) {
    EXPECT_TRUE(after.count(name) && after.at(name) == bytes)
        << tool << ": " << name << " is not the old file any more";
  }
}

TEST(ToolOutputSets, AllanWithOneReportFileBlockedKeepsTheWholeOldReport) {
  const std::string inputs = scratch_directory();
  const std::string report = scratch_directory() + "/report";
  const std::string first = white_noise_bag(inputs + "/first.bag", 1);
  const std::string second = white_noise_bag(inputs + "/second.bag", 2);
  // The summary is written after the nine curves and the noise files.
  expect_old_set_kept("allan", first + " --out " + report, second + " --out " + report, report, "allan_summary.yaml");
}

TEST(ToolOutputSets, FitCalibrationWithItsReportBlockedKeepsTheOldCalibration) {
  const std::string directory = scratch_directory();
  const std::string schedule = write_quick_twelve_position_schedule(directory);
  const std::string outputs = scratch_directory();
  for (const char* seed : {"2", "3"}) {
    ASSERT_EQ(run_tool("emulate", "--profile tactical_mems --scenario " + schedule + " --rate-hz 100 --seed " + seed +
                                      " --out " + directory + "/cal" + seed + ".bag")
                  .exit_code,
              0);
  }
  const std::string options = " --schedule " + schedule + " -o " + outputs + "/cal.yaml";
  expect_old_set_kept("fit_calibration", directory + "/cal2.bag" + options, directory + "/cal3.bag" + options, outputs,
                      "cal_report.txt");
}

TEST(ToolOutputSets, FitThermalWithItsResidualsBlockedKeepsTheOldModel) {
  const std::string directory = scratch_directory();
  const std::string outputs = scratch_directory();
  for (const char* seed : {"11", "12"}) {
    ASSERT_EQ(run_tool("emulate", "--profile " + kData + "/thermal/uncompensated_mems_gyro.yaml --scenario " + kData +
                                      "/thermal/fit_multiposition.yaml --rate-hz 2 --no-truth --no-increments --seed " +
                                      seed + " --out " + directory + "/thermal" + seed + ".bag")
                  .exit_code,
              0);
  }
  const std::string options = " --latitude-deg 50.45 --height-m 180 -o " + outputs + "/model.yaml";
  expect_old_set_kept("fit_thermal", directory + "/thermal11.bag" + options, directory + "/thermal12.bag" + options,
                      outputs, "model_residuals.csv");
}

TEST(ToolOutputSets, NavigateWithItsErrorsBlockedKeepsTheOldTrajectory) {
  const std::string directory = scratch_directory();
  const std::string outputs = scratch_directory();
  for (const char* seed : {"1", "2"}) {
    ASSERT_EQ(run_tool("emulate", "--profile rlg_navigation --scenario static --duration-s 20 --rate-hz 50 --seed " +
                                      std::string(seed) + " --out " + directory + "/drive" + seed + ".bag")
                  .exit_code,
              0);
  }
  const std::string options = " --topic /imu/raw --alignment-duration-s 5 -o " + outputs + "/trajectory.csv";
  expect_old_set_kept("navigate", directory + "/drive1.bag" + options, directory + "/drive2.bag" + options, outputs,
                      "trajectory_errors.csv");
}

// ---- A triad marked as not provided ----

TEST(ToolsTriadNotProvided, AllanAndBagSummaryLeaveItOutTheOthersRefuseNamingIt) {
  ImuBagLayout layout = with_temperature();
  layout.without_angular_rate = true;
  const std::string bag = white_noise_bag(scratch_directory() + "/accelerometer_only.bag", 3, layout);
  const std::string outputs = scratch_directory();

  const CommandResult allan = run_tool("allan", bag + " --no-plot --no-identify --out " + outputs + "/report");
  ASSERT_EQ(allan.exit_code, 0) << allan.output;
  EXPECT_TRUE(contains(allan.output, "3000 of 3000 messages mark the gyro triad as not provided")) << allan.output;
  const YAML::Node summary = read_allan_summary(outputs + "/report");
  EXPECT_EQ(summary["channels"]["gyro_x"]["finite_samples"].as<long>(), 0) << "the zeros must not be analysed";
  EXPECT_EQ(summary["channels"]["accel_x"]["finite_samples"].as<long>(), 3000);

  const CommandResult table = run_tool("bag_summary", bag);
  ASSERT_EQ(table.exit_code, 0) << table.output;
  EXPECT_TRUE(contains(table.output, "no message carries the gyro triad")) << table.output;
  EXPECT_FALSE(contains(table.output, "\ngyro_x ")) << table.output;
  EXPECT_TRUE(contains(table.output, "\naccel_x ")) << table.output;

  struct Refusing {
    std::string tool, arguments;
  };
  for (const Refusing& tool :
       {Refusing{"fit_calibration", " --latitude-deg 50 --height-m 0 --out " + outputs + "/cal.yaml"},
        Refusing{"fit_thermal", " --no-scale-factor --out " + outputs + "/model.yaml"},
        Refusing{"correct", " --calibration " + kData + "/calibration_example.yaml --out " + outputs + "/c.bag"}}) {
    const CommandResult result = run_tool(tool.tool, bag + tool.arguments);
    EXPECT_EQ(result.exit_code, 1) << tool.tool << ": " << result.output;
    EXPECT_TRUE(contains(result.output, bag + ", topic /imu/raw: 3000 of 3000 messages without angular rate"))
        << result.output;
  }
  const CommandResult navigate = run_tool("navigate", bag +
                                                          " --latitude-deg 50 --longitude-deg 10 --height-m 0 "
                                                          "--alignment-duration-s 10 --out " +
                                                          outputs + "/t.csv");
  EXPECT_EQ(navigate.exit_code, 1) << navigate.output;
  EXPECT_TRUE(contains(navigate.output, bag)) << navigate.output;
  EXPECT_EQ(list_directory(outputs), std::vector<std::string>{"report"});
}

// ---- Values that cannot be used ----

TEST(ToolsUnusableValues, AllanLeavesExtremeValuesOutAndRefusesABagWithoutAnyUsableOne) {
  const std::string inputs = scratch_directory();
  const std::string outputs = scratch_directory();
  auto samples = white_noise_samples(3000, kInterval_ns, 4);
  for (const std::size_t i : {100, 1500, 2500}) samples[i].values[1] = 1e308;
  const std::string extreme = inputs + "/extreme.bag";
  write_imu_bag(extreme, samples);
  const CommandResult allan = run_tool("allan", extreme + " --no-plot --out " + outputs + "/report");
  ASSERT_EQ(allan.exit_code, 0) << allan.output;  // was exit 1: the noise-type estimate threw
  EXPECT_TRUE(contains(allan.output, "3 NaN/Inf or unusable values")) << allan.output;
  EXPECT_EQ(read_allan_summary(outputs + "/report")["channels"]["gyro_y"]["non_finite_samples"].as<int>(), 3);

  const CommandResult summary = run_tool("bag_summary", extreme);
  EXPECT_EQ(summary.exit_code, 1) << summary.output;
  EXPECT_TRUE(contains(summary.output, extreme + ", topic /imu/raw: 3 samples with NaN/Inf (or beyond +-1e100)"))
      << summary.output;
  // navigate integrated them (exit 0, a trajectory of overflowed numbers); now refused like NaN.
  const CommandResult navigate = run_tool("navigate", extreme +
                                                          " --latitude-deg 50 --longitude-deg 30 --height-m 0 "
                                                          "--alignment-duration-s 1 -o " +
                                                          outputs + "/trajectory.csv");
  EXPECT_EQ(navigate.exit_code, 1) << navigate.output;
  EXPECT_TRUE(contains(navigate.output, "3 samples with NaN/Inf, a value beyond +-1e100")) << navigate.output;
  EXPECT_FALSE(file_exists(outputs + "/trajectory.csv"));

  for (auto& sample : samples) {
    for (double& value : sample.values) value = std::numeric_limits<double>::quiet_NaN();
  }
  const std::string nothing = inputs + "/nothing.bag";
  write_imu_bag(nothing, samples);
  const CommandResult empty = run_tool("allan", nothing + " --no-plot --out " + outputs + "/empty");
  EXPECT_EQ(empty.exit_code, 1) << empty.output;  // was exit 0 with empty curves
  EXPECT_TRUE(contains(empty.output, nothing + ", topic /imu/raw: none of the 3000 messages has a usable value"))
      << empty.output;
  EXPECT_FALSE(file_exists(outputs + "/empty"));
}

// Errors raised inside the fits reached the user without the bag's name.
TEST(ToolsRefusalsNameTheBag, ErrorsFromInsideTheFitsNameTheBagAndTopic) {
  auto samples = white_noise_samples(6000, kInterval_ns, 5);
  for (auto& sample : samples) {
    for (std::size_t c = 0; c < 3; ++c) sample.values[c] *= 1000.0;  // 1 rad/s of noise: never at rest
  }
  const std::string bag = scratch_directory() + "/moving.bag";
  write_imu_bag(bag, samples, with_temperature());
  const std::string outputs = scratch_directory();
  const CommandResult calibration =
      run_tool("fit_calibration", bag + " --latitude-deg 50 --height-m 0 --out " + outputs + "/cal.yaml");
  EXPECT_EQ(calibration.exit_code, 1) << calibration.output;
  EXPECT_TRUE(contains(calibration.output, "fit_calibration: bag " + bag + ", topic /imu/raw: ")) << calibration.output;
  const CommandResult thermal = run_tool("fit_thermal", bag + " --no-scale-factor --out " + outputs + "/model.yaml");
  EXPECT_EQ(thermal.exit_code, 1) << thermal.output;
  EXPECT_TRUE(contains(thermal.output, "fit_thermal: bag " + bag + ", topic /imu/raw: ")) << thermal.output;
  EXPECT_TRUE(contains(thermal.output, "no static window")) << thermal.output;
  EXPECT_EQ(list_directory(outputs), std::vector<std::string>{});
}

// ---- The site, and one output option for all ----

TEST(FitToolsSite, TheSiteIsRequiredWhereItMattersAndAConflictIsRefused) {
  const std::string bag = white_noise_bag(scratch_directory() + "/rest.bag", 6, with_temperature());
  const std::string out = scratch_directory() + "/out.yaml";
  const CommandResult no_site = run_tool("fit_calibration", bag + " -o " + out);
  EXPECT_EQ(no_site.exit_code, 2) << no_site.output;  // was: latitude 0, height 0, exit 0
  EXPECT_TRUE(contains(no_site.output, "give the site's latitude and height")) << no_site.output;
  const CommandResult conflict = run_tool("fit_calibration", bag +
                                                                 " --schedule multiposition_12_thesis "
                                                                 "--latitude-deg 50 -o " +
                                                                 out);
  EXPECT_EQ(conflict.exit_code, 2) << conflict.output;  // --schedule used to override it silently
  EXPECT_TRUE(contains(conflict.output, "--schedule excludes --latitude-deg")) << conflict.output;
  const CommandResult thermal = run_tool("fit_thermal", bag + " -o " + out);
  EXPECT_EQ(thermal.exit_code, 2) << thermal.output;  // was: latitude 45
  EXPECT_TRUE(contains(thermal.output, "--latitude-deg: give the test site's latitude")) << thermal.output;
  EXPECT_FALSE(file_exists(out));
}

// A calibration fitted at the wrong site (latitude 0 instead of 50.45): chi2/dof 32, which used to
// be the only clue.
TEST(FitToolsSite, AFitFarAboveItsNoiseIsWarnedAbout) {
  const std::string directory = scratch_directory();
  const std::string bag = directory + "/cal.bag";
  ASSERT_EQ(run_tool("emulate",
                     "--profile tactical_mems --scenario multiposition_12_thesis --rate-hz 100 --seed 3 "
                     "--no-truth --no-increments --out " +
                         bag)
                .exit_code,
            0);
  const CommandResult wrong =
      run_tool("fit_calibration", bag + " --latitude-deg 0 --height-m 0 -o " + directory + "/w.yaml");
  ASSERT_EQ(wrong.exit_code, 0) << wrong.output;
  EXPECT_TRUE(contains(wrong.output, "fit_calibration: warning: the calibration fit: chi2/dof")) << wrong.output;
  EXPECT_TRUE(contains(wrong.output, "are the latitude and height the site's")) << wrong.output;
  EXPECT_TRUE(contains(read_file(directory + "/w_report.txt"), "WARNING: the calibration fit: chi2/dof"));
  const CommandResult right =
      run_tool("fit_calibration", bag + " --latitude-deg 50.45 --height-m 180 -o " + directory + "/r.yaml");
  ASSERT_EQ(right.exit_code, 0) << right.output;
  EXPECT_FALSE(contains(right.output, "warning")) << right.output;
}

// ---- CSV files as they come ----

std::string write_text(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

std::vector<imu_lab::io::ImuRecord> records_of(const std::string& bag) {
  std::vector<imu_lab::io::ImuRecord> records;
  imu_lab::ros_io::for_each_imu(bag, "/imu/raw", [&](const imu_lab::io::ImuRecord& r) { records.push_back(r); });
  return records;
}

TEST(ImportCsvFormats, EurocHeadersAreRecognisedWithNoOptions) {
  const std::string directory = scratch_directory();
  std::string text =
      "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],"
      "a_RS_S_x [m s^-2],a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]\n";
  for (int i = 0; i < 50; ++i) {
    text += std::to_string(1403636579758555392LL + 5000000LL * i) + ",-0.0991,0.1403,0.0251,8.1125,-1.9613,-2.6031\n";
  }
  const std::string csv = write_text(directory + "/data.csv", text);
  const CommandResult result = run_tool("import_csv", csv + " -o " + directory + "/euroc.bag");
  ASSERT_EQ(result.exit_code, 0) << result.output;  // was: "line 2 is numbers, not a header line"
  EXPECT_TRUE(contains(result.output, "EuRoC/ASL format")) << result.output;
  EXPECT_TRUE(contains(result.output, "units from the header: time ns, gyro rad_s, accel m_s2")) << result.output;
  const auto records = records_of(directory + "/euroc.bag");
  ASSERT_EQ(records.size(), 50u);
  EXPECT_EQ(records[0].stamp_ns, 1403636579758555392LL) << "absolute ns stamps kept exactly";
  EXPECT_DOUBLE_EQ(records[0].angular_rate_rad_s.y(), 0.1403);
  EXPECT_DOUBLE_EQ(records[0].specific_force_m_s2.x(), 8.1125);
  // A unit given that the header contradicts is refused: one of them is wrong.
  const CommandResult conflict = run_tool("import_csv", csv + " -o " + directory + "/x.bag --gyro-unit deg_s");
  EXPECT_EQ(conflict.exit_code, 2) << conflict.output;
  EXPECT_TRUE(contains(conflict.output, "'deg_s' given, but the header names the gyro columns in rad s^-1"))
      << conflict.output;
}

TEST(ImportCsvFormats, ARelativeTimeColumnIsOffsetAndSaidAbsoluteOnesAreKept) {
  const std::string directory = scratch_directory();
  std::string relative = "t_ms,gx,gy,gz,ax,ay,az\n";
  for (int i = 0; i < 20; ++i) relative += std::to_string(10 * i) + ",0,0,0,0,0,9.8\n";
  const CommandResult result =
      run_tool("import_csv", write_text(directory + "/logger.csv", relative) + " -o " + directory + "/logger.bag");
  ASSERT_EQ(result.exit_code, 0) << result.output;  // was: time 0 is outside ROS time
  EXPECT_TRUE(contains(result.output, "the time column is relative (it starts at 0.000000000 s")) << result.output;
  EXPECT_TRUE(contains(result.output, "1000000000.000000000 s added to every stamp")) << result.output;
  const auto records = records_of(directory + "/logger.bag");
  ASSERT_EQ(records.size(), 20u);
  EXPECT_EQ(records[0].stamp_ns, 1'000'000'000LL * 1'000'000'000LL);
  EXPECT_EQ(records[1].stamp_ns - records[0].stamp_ns, 10'000'000) << "ms from the header's unit";

  std::string absolute = "time_s,gx,gy,gz,ax,ay,az\n1700000000.5,0,0,0,0,0,9.8\n1700000000.6,0,0,0,0,0,9.8\n";
  const CommandResult kept =
      run_tool("import_csv", write_text(directory + "/absolute.csv", absolute) + " -o " + directory + "/absolute.bag");
  ASSERT_EQ(kept.exit_code, 0) << kept.output;
  EXPECT_FALSE(contains(kept.output, "relative")) << kept.output;
  EXPECT_EQ(records_of(directory + "/absolute.bag")[0].stamp_ns, 1700000000500000000LL);
}

TEST(ImportCsvFormats, AHugeLineIsABadRowNotAMemoryHog) {
  const std::string directory = scratch_directory();
  std::string text = "time_s,gx,gy,gz,ax,ay,az\n1700000000.0,0,0,0,0,0,9.8\n";
  text += std::string(1 << 20, '7') + "\n";  // 1 MiB on one line (a broken line end, a binary file)
  text += "1700000000.1,0,0,0,0,0,9.8\n";
  const std::string csv = write_text(directory + "/damaged.csv", text);
  const CommandResult refused = run_tool("import_csv", csv + " -o " + directory + "/out.bag");
  EXPECT_EQ(refused.exit_code, 1) << refused.output.substr(0, 2000);
  EXPECT_TRUE(contains(refused.output, "line 3: longer than 65536 bytes")) << refused.output.substr(0, 2000);
  EXPECT_LT(refused.output.size(), 2000u) << "the line itself is not echoed";
  const CommandResult skipped = run_tool("import_csv", csv + " -o " + directory + "/out.bag --on-bad-row skip");
  EXPECT_EQ(skipped.exit_code, 0) << skipped.output.substr(0, 2000);
  EXPECT_EQ(records_of(directory + "/out.bag").size(), 2u);
}

// ---- The package's files without a sourced workspace ----

// What a new user's shell has before `source devel/setup.bash`: no ROS_PACKAGE_PATH at all.
std::string unsourced(const std::string& tool, const std::string& arguments) {
  return "env -i PATH=/usr/bin:/bin HOME=/tmp " + tool_path(tool) + " " + arguments;
}

TEST(PackageFiles, ToolsFindTheirConfigurationAndScriptsWithoutASourcedWorkspace) {
  const std::string directory = scratch_directory();
  const CommandResult emulate =
      run_command(unsourced("emulate", "--scenario coning --duration-s 2 --rate-hz 100 --out " + directory + "/c.bag"));
  EXPECT_EQ(emulate.exit_code, 0) << emulate.output;  // was: no shipped configuration /config/scenarios/coning.yaml
  const CommandResult allan =
      run_command(unsourced("allan", directory + "/c.bag --no-identify --out " + directory + "/r"));
  EXPECT_EQ(allan.exit_code, 0) << allan.output;
  EXPECT_TRUE(file_exists(directory + "/r/allan.png")) << "no plot without a sourced workspace:\n" << allan.output;
}

TEST(PackageFiles, AFileNotFoundSaysWhatToSource) {
  try {
    imu_lab::ros_io::find_package_file("scripts/plot_allan.py", {"/nonexistent/share/imu_lab"});
    FAIL() << "expected a ConfigError";
  } catch (const imu_lab::ConfigError& error) {
    EXPECT_TRUE(contains(error.what(), "/nonexistent/share/imu_lab/scripts/plot_allan.py")) << error.what();
    EXPECT_TRUE(contains(error.what(), "source the workspace's setup.bash")) << error.what();
  }
  EXPECT_EQ(imu_lab::ros_io::package_file("scripts/plot_allan.py").substr(0, 1), "/");
}

// ---- correct's summary ----

// A model without a rate term has no rate range that could clamp: correct used to print one.
TEST(CorrectSummary, ARateRangeIsPrintedOnlyForAModelWithARateTerm) {
  const std::string directory = scratch_directory();
  std::string model = read_file(kData + "/thermal/model_uncompensated_mems_gyro.yaml");
  model.replace(model.find("uses_temperature_rate: true"), 27, "uses_temperature_rate: false");
  write_text(directory + "/static_model.yaml", model);
  const std::string bag = white_noise_bag(directory + "/warm.bag", 7, with_temperature());
  const CommandResult without_rate =
      run_tool("correct", bag + " --thermal-model " + directory + "/static_model.yaml --out " + directory + "/a.bag");
  ASSERT_EQ(without_rate.exit_code, 0) << without_rate.output;
  EXPECT_FALSE(contains(without_rate.output, "degC/s")) << without_rate.output;
  const CommandResult with_rate =
      run_tool("correct", bag + " --thermal-model " + kData + "/thermal/model_uncompensated_mems_gyro.yaml --out " +
                              directory + "/b.bag");
  ASSERT_EQ(with_rate.exit_code, 0) << with_rate.output;
  EXPECT_TRUE(contains(with_rate.output, "degC/s")) << with_rate.output;
}

}  // namespace
