// import_csv and export_csv, run as a user runs them: bags and CSVs on disk, exit codes, messages.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "ros_test_support.h"

#ifndef IMU_LAB_CONFIG_DIR
#define IMU_LAB_CONFIG_DIR "config"
#endif

namespace {

using imu_lab::io::ImuRecord;
using imu_lab::io::TemperatureRecord;
using imu_lab::test_support::file_exists;
using imu_lab::test_support::list_directory;
using imu_lab::test_support::read_file;
using imu_lab::test_support::run_tool;
using imu_lab::test_support::scratch_directory;

std::vector<ImuRecord> read_imu(const std::string& bag, const std::string& topic = "/imu/raw") {
  std::vector<ImuRecord> records;
  imu_lab::ros_io::for_each_imu(bag, topic, [&](const ImuRecord& record) { records.push_back(record); });
  return records;
}

std::vector<TemperatureRecord> read_temperatures(const std::string& bag) {
  std::vector<TemperatureRecord> records;
  imu_lab::ros_io::for_each_temperature(bag, "/imu/temperature",
                                        [&](const TemperatureRecord& record) { records.push_back(record); });
  return records;
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

using imu_lab::test_support::contains;

// A logger's file: semicolons, decimal commas, ms since boot, deg/s, g, a temperature column
// that is empty where the thermosensor had no new reading.
const std::string kLoggerCsv =
    "# logger firmware 1.2\n"
    "t_ms;ax;ay;az;gx;gy;gz;temp_c\n"
    "1000;0;0;1;0,5;0;-1;24,5\n"
    "1010;0;0;1,001;0,5;0;-1;\n"
    "1020;0,002;0;1;0,25;0;-1;24,75\n";

const std::string kLoggerYaml =
    "delimiter: ';'\n"
    "decimal_comma: true\n"
    "time: {column: t_ms, unit: ms, offset_s: 1700000000}\n"
    "gyro: {columns: [gx, gy, gz], unit: deg_s}\n"
    "accel: {columns: [ax, ay, az], unit: g}\n"
    "temperature: {column: temp_c}\n";

TEST(ImportCsvTool, LoggerFileWithAYamlMappingBecomesImuAndTemperatureMessages) {
  const std::string directory = scratch_directory();
  write(directory + "/log.csv", kLoggerCsv);
  write(directory + "/logger.yaml", kLoggerYaml);
  const auto result = run_tool(
      "import_csv", directory + "/log.csv --config " + directory + "/logger.yaml -o " + directory + "/log.bag");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "3 samples on /imu/raw (time ms, gyro deg_s, accel g)")) << result.output;
  EXPECT_TRUE(contains(result.output, "2 temperatures on /imu/temperature (1 rows without one)")) << result.output;
  const auto imu = read_imu(directory + "/log.bag");
  ASSERT_EQ(imu.size(), 3u);
  EXPECT_EQ(imu[0].stamp_ns, 1700000001000000000LL);
  EXPECT_EQ(imu[2].stamp_ns, 1700000001020000000LL);
  EXPECT_DOUBLE_EQ(imu[0].angular_rate_rad_s.x(), 0.5 * M_PI / 180.0);
  EXPECT_DOUBLE_EQ(imu[0].angular_rate_rad_s.z(), -M_PI / 180.0);
  EXPECT_DOUBLE_EQ(imu[1].specific_force_m_s2.z(), 1.001 * 9.80665);
  EXPECT_DOUBLE_EQ(imu[2].specific_force_m_s2.x(), 0.002 * 9.80665);
  const auto temperatures = read_temperatures(directory + "/log.bag");
  ASSERT_EQ(temperatures.size(), 2u);
  EXPECT_DOUBLE_EQ(temperatures[1].temperature_c, 24.75);
  EXPECT_EQ(temperatures[1].stamp_ns, imu[2].stamp_ns);

  // The same by options alone; an option overrides the YAML.
  const auto by_options =
      run_tool("import_csv", directory +
                                 "/log.csv --delimiter ';' --decimal-comma --time-column t_ms --time-unit ms "
                                 "--time-offset-s 1700000000 --gyro-columns gx,gy,gz --gyro-unit deg_s "
                                 "--accel-columns ax,ay,az --accel-unit g -o " +
                                 directory + "/options.bag");
  ASSERT_EQ(by_options.exit_code, 0) << by_options.output;
  const auto same = read_imu(directory + "/options.bag");
  ASSERT_EQ(same.size(), 3u);
  EXPECT_EQ(same[2].specific_force_m_s2, imu[2].specific_force_m_s2);
  EXPECT_EQ(imu_lab::ros_io::list_topics(directory + "/options.bag").size(), 1u);  // no temperature column mapped
}

const std::string kDamagedCsv =
    "t,gx,gy,gz,ax,ay,az\n"
    "1,0,0,0,0,0,9.8\n"
    "2,0,0,0,0,0\n"  // line 3: a field missing
    "3,0,0,0,0,0,9.8\n"
    "4,0,nan,0,0,0,9.8\n"  // line 5: NaN
    "2.5,0,0,0,0,0,9.8\n"  // line 6: time goes back
    "5,0,0,0,0,0,9.8\n";

TEST(ImportCsvTool, RefusesABadFileByDefaultListingEveryBadLineAndWritesNothing) {
  const std::string directory = scratch_directory();
  write(directory + "/damaged.csv", kDamagedCsv);
  const auto result = run_tool("import_csv", directory + "/damaged.csv -o " + directory + "/never.bag");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "damaged.csv: 3 bad rows of 6 data rows")) << result.output;
  EXPECT_TRUE(contains(result.output, "line 3: 6 fields, expected 7 as in the header")) << result.output;
  EXPECT_TRUE(contains(result.output, "line 5: column 3 (gy): 'nan' is not a finite number")) << result.output;
  EXPECT_TRUE(contains(result.output, "line 6: time 2.500000000 s is not after the previous good row's 3.000000000 s"))
      << result.output;
  EXPECT_TRUE(contains(result.output, "nothing written")) << result.output;
  EXPECT_EQ(list_directory(directory), std::vector<std::string>{"damaged.csv"});
}

TEST(ImportCsvTool, SkipPolicyImportsTheGoodRowsAndStillReportsEachBadOne) {
  const std::string directory = scratch_directory();
  write(directory + "/damaged.csv", kDamagedCsv);
  const auto result = run_tool(
      "import_csv", directory + "/damaged.csv --on-bad-row skip --max-reported-rows 2 -o " + directory + "/good.bag");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "skipped " + directory + "/damaged.csv: 3 bad rows of 6 data rows"))
      << result.output;
  EXPECT_TRUE(contains(result.output, "line 3:")) << result.output;
  EXPECT_TRUE(contains(result.output, "line 5:")) << result.output;
  EXPECT_TRUE(contains(result.output, "... and 1 more")) << result.output;
  EXPECT_TRUE(contains(result.output, "; 3 bad rows skipped")) << result.output;
  const auto imu = read_imu(directory + "/good.bag");
  ASSERT_EQ(imu.size(), 3u);
  EXPECT_EQ(imu[2].stamp_ns, 1'000'000'000'000'000'000LL + 5000000000LL);  // a relative time column, moved by 1e9 s
}

TEST(ImportCsvTool, AMappingThatDoesNotFitIsABadConfigurationAndWritesNothing) {
  const std::string directory = scratch_directory();
  write(directory + "/log.csv", kLoggerCsv);
  write(directory + "/typo.yaml", "gyro: {colums: [gx, gy, gz]}\n");
  const std::pair<std::string, std::string> cases[] = {
      {"--delimiter ';' --time-column time", "time_column: no column 'time' in the header (it has: t_ms, ax"},
      {"--delimiter ';' --gyro-unit dps", "--gyro-unit: unknown angular-rate unit 'dps'"},
      {"--delimiter ';' --on-bad-row ignore", "--on-bad-row: unknown policy 'ignore'"},
      {"--delimiter ';' --gyro-columns 5,6", "--gyro-columns: needs three columns"},
      {"--config " + directory + "/typo.yaml", "typo.yaml: gyro.colums: unknown key"},
      {"--config " + directory + "/none.yaml", "none.yaml: (file): cannot read"},
      {"--no-header", "column 7 is mapped, but line 2 has 1 field (check the delimiter"},
  };
  for (const auto& [arguments, message] : cases) {
    const auto result = run_tool("import_csv", directory + "/log.csv " + arguments + " -o " + directory + "/x.bag");
    EXPECT_EQ(result.exit_code, 2) << arguments << "\n" << result.output;
    EXPECT_TRUE(contains(result.output, "import_csv: bad configuration: ")) << result.output;
    EXPECT_TRUE(contains(result.output, message)) << arguments << "\n" << result.output;
  }
  EXPECT_FALSE(file_exists(directory + "/x.bag"));
  const auto missing = run_tool("import_csv", directory + "/absent.csv -o " + directory + "/x.bag");
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_TRUE(contains(missing.output, "cannot read " + directory + "/absent.csv")) << missing.output;
  EXPECT_EQ(list_directory(directory), (std::vector<std::string>{"log.csv", "typo.yaml"}));
}

TEST(CsvTools, EmulatedBagExportsImportsAndExportsAgainUnchanged) {
  const std::string directory = scratch_directory();
  const std::string original = directory + "/emulated.bag";
  const auto emulated =
      run_tool("emulate", "--profile " + std::string(IMU_LAB_CONFIG_DIR) + "/sensors/tactical_mems.yaml --scenario " +
                              std::string(IMU_LAB_CONFIG_DIR) +
                              "/scenarios/static.yaml --duration-s 5 --rate-hz 100 --seed 2 --out " + original);
  ASSERT_EQ(emulated.exit_code, 0) << emulated.output;

  const auto exported = run_tool("export_csv", original + " -o " + directory + "/first.csv");
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  EXPECT_TRUE(contains(exported.output,
                       "500 rows of /imu/raw (gyro rad_s, accel m_s2), temperature_c from "
                       "/imu/temperature in 500 rows"))
      << exported.output;
  const std::string first = read_file(directory + "/first.csv");
  EXPECT_EQ(first.substr(0, first.find('\n')),
            "time_s,gyro_x_rad_s,gyro_y_rad_s,gyro_z_rad_s,accel_x_m_s2,accel_y_m_s2,accel_z_m_s2,temperature_c");

  const auto imported =
      run_tool("import_csv", directory + "/first.csv --temperature-column temperature_c -o " + directory + "/back.bag");
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  const auto again = run_tool("export_csv", directory + "/back.bag -o " + directory + "/second.csv");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_TRUE(first == read_file(directory + "/second.csv")) << "import -> export must reproduce the file";

  // And the samples are the emulator's, bit for bit.
  const auto before = read_imu(original);
  const auto after = read_imu(directory + "/back.bag");
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    ASSERT_EQ(before[i].stamp_ns, after[i].stamp_ns) << i;
    ASSERT_EQ(before[i].angular_rate_rad_s, after[i].angular_rate_rad_s) << i;
    ASSERT_EQ(before[i].specific_force_m_s2, after[i].specific_force_m_s2) << i;
  }
  const auto temperatures_before = read_temperatures(original);
  const auto temperatures_after = read_temperatures(directory + "/back.bag");
  ASSERT_EQ(temperatures_before.size(), temperatures_after.size());
  EXPECT_EQ(temperatures_before.back().temperature_c, temperatures_after.back().temperature_c);

  // Field units: deg/s and g, tab-separated, read back with the matching options.
  const auto field = run_tool("export_csv", original +
                                                " --gyro-unit deg_s --accel-unit g --delimiter tab "
                                                "--no-temperature -o " +
                                                directory + "/field.csv");
  ASSERT_EQ(field.exit_code, 0) << field.output;
  const std::string field_text = read_file(directory + "/field.csv");
  EXPECT_EQ(field_text.substr(0, field_text.find('\n')),
            "time_s\tgyro_x_deg_s\tgyro_y_deg_s\tgyro_z_deg_s\taccel_x_g\taccel_y_g\taccel_z_g");
  const auto field_back = run_tool("import_csv", directory +
                                                     "/field.csv --delimiter tab --gyro-unit deg_s "
                                                     "--accel-unit g -o " +
                                                     directory + "/field.bag");
  ASSERT_EQ(field_back.exit_code, 0) << field_back.output;
  const auto converted = read_imu(directory + "/field.bag");
  ASSERT_EQ(converted.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(converted[i].stamp_ns, before[i].stamp_ns);
    EXPECT_LT((converted[i].angular_rate_rad_s - before[i].angular_rate_rad_s).norm(),
              1e-15 * before[i].angular_rate_rad_s.norm() + 1e-300);
    EXPECT_LT((converted[i].specific_force_m_s2 - before[i].specific_force_m_s2).norm(),
              1e-15 * before[i].specific_force_m_s2.norm());
  }
}

// Issue 46: a relative time column gets import_csv's 1e9 s; export_csv --time-offset-s takes the
// same number off again, so the file's own times come back. The import's hint says which offsets
// work: for a file starting at 0, "0 keeps it" was a refusal (ROS time starts after 0 s); the
// offset it suggests now imports, and for a file starting later 0 does keep the times.
TEST(CsvTools, TheImportsTimeOffsetComesOffAgainAndItsHintWorks) {
  const std::string directory = scratch_directory();
  const std::string rows = "0.25,0,0,0,0,0,9.8\n0.5,0,0,0,0,0,9.8\n";
  write(directory + "/from_zero.csv", "t,gx,gy,gz,ax,ay,az\n0,0,0,0,0,0,9.8\n" + rows);
  const auto imported = run_tool("import_csv", directory + "/from_zero.csv -o " + directory + "/from_zero.bag");
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  EXPECT_TRUE(contains(imported.output, "1000000000.000000000 s added to every stamp")) << imported.output;
  EXPECT_FALSE(contains(imported.output, "0 keeps")) << imported.output;
  const std::string suggestion = "e.g. --time-offset-s ";
  const auto at = imported.output.find(suggestion);
  ASSERT_NE(at, std::string::npos) << imported.output;
  const std::string suggested = imported.output.substr(at + suggestion.size(), 1);
  EXPECT_EQ(suggested, "1");
  const auto as_suggested = run_tool(
      "import_csv", directory + "/from_zero.csv --time-offset-s " + suggested + " -o " + directory + "/suggested.bag");
  EXPECT_EQ(as_suggested.exit_code, 0) << as_suggested.output;
  EXPECT_EQ(read_imu(directory + "/suggested.bag").front().stamp_ns, 1000000000);

  const auto exported =
      run_tool("export_csv", directory + "/from_zero.bag --time-offset-s 1000000000 -o " + directory + "/back.csv");
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  EXPECT_TRUE(contains(read_file(directory + "/back.csv"), "\n0.000000000,0,0,0,0,0,9.8\n0.250000000,"))
      << read_file(directory + "/back.csv");
  const auto bad_offset =
      run_tool("export_csv", directory + "/from_zero.bag --time-offset-s 1e9x -o " + directory + "/x.csv");
  EXPECT_EQ(bad_offset.exit_code, 2) << bad_offset.output;
  EXPECT_TRUE(contains(bad_offset.output, "--time-offset-s")) << bad_offset.output;
  EXPECT_FALSE(file_exists(directory + "/x.csv"));

  write(directory + "/later.csv", "t,gx,gy,gz,ax,ay,az\n" + rows);
  const auto later = run_tool("import_csv", directory + "/later.csv -o " + directory + "/later.bag");
  ASSERT_EQ(later.exit_code, 0) << later.output;
  EXPECT_TRUE(contains(later.output, "0 keeps the file's times")) << later.output;
  const auto kept = run_tool("import_csv", directory + "/later.csv --time-offset-s 0 -o " + directory + "/kept.bag");
  ASSERT_EQ(kept.exit_code, 0) << kept.output;
  EXPECT_EQ(read_imu(directory + "/kept.bag").front().stamp_ns, 250000000);
}

TEST(ExportCsvTool, RefusesAMissingTopicOrUnitAndWritesNothing) {
  const std::string directory = scratch_directory();
  write(directory + "/log.csv", "t,gx,gy,gz,ax,ay,az\n1,0,0,0,0,0,9.8\n2,0,0,0,0,0,9.8\n");
  ASSERT_EQ(run_tool("import_csv", directory + "/log.csv -o " + directory + "/log.bag").exit_code, 0);
  const auto wrong_topic = run_tool("export_csv", directory + "/log.bag --topic /imu/data -o " + directory + "/x.csv");
  EXPECT_EQ(wrong_topic.exit_code, 1) << wrong_topic.output;
  EXPECT_TRUE(contains(wrong_topic.output,
                       "has no topic /imu/data; topics in the bag:\n  /imu/raw (sensor_msgs/Imu, 2 "
                       "messages)"))
      << wrong_topic.output;
  const auto no_temperature =
      run_tool("export_csv", directory + "/log.bag --temperature-topic /imu/temperature -o " + directory + "/x.csv");
  EXPECT_EQ(no_temperature.exit_code, 1) << no_temperature.output;
  const auto bad_unit = run_tool("export_csv", directory + "/log.bag --accel-unit mg -o " + directory + "/x.csv");
  EXPECT_EQ(bad_unit.exit_code, 2) << bad_unit.output;
  EXPECT_TRUE(contains(bad_unit.output, "--accel-unit: unknown specific-force unit 'mg'")) << bad_unit.output;
  const auto not_a_bag = run_tool("export_csv", directory + "/log.csv -o " + directory + "/x.csv");
  EXPECT_EQ(not_a_bag.exit_code, 1) << not_a_bag.output;
  EXPECT_EQ(list_directory(directory), (std::vector<std::string>{"log.bag", "log.csv"}));
}

}  // namespace
