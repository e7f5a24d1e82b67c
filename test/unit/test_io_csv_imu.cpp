// The logger-CSV parser (io/csv_imu_import.h), its YAML column mapping and the CSV writer.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "imu_lab/common/config_error.h"
#include "imu_lab/io/csv_import_config.h"
#include "imu_lab/io/csv_imu_export.h"
#include "imu_lab/io/csv_imu_import.h"

namespace {

using imu_lab::ConfigError;
using imu_lab::InputError;
using namespace imu_lab::io;

constexpr double kDeg = M_PI / 180.0;
constexpr double kG = 9.80665;

CsvImportOptions plain() { return CsvImportOptions{}; }

// Seven columns t, gx..gz, ax..az with a header line.
const std::string kHeader = "t,gx,gy,gz,ax,ay,az\n";

std::string rejection_lines(const CsvImportSummary& summary) {
  std::string lines;
  for (const auto& row : summary.rejected) lines += std::to_string(row.line) + " ";
  return lines;
}

TEST(CsvImuImport, ReadsNamedColumnsAndConvertsUnitsToSi) {
  const std::string text =
      "time_ms;temp;wx;wy;wz;fx;fy;fz\n"
      "1000,5;21,5;1,0;-2;0,5;0;0;1\n"
      "1010,5;;90;0;0;0,5;-1;0\n";
  CsvImportOptions options;
  options.delimiter = ';';
  options.decimal_comma = true;
  options.time_column = "time_ms";
  options.time_unit = TimeUnit::kMillisecond;
  options.gyro_columns = {"wx", "wy", "wz"};
  options.gyro_unit = AngularRateUnit::kDegreePerSecond;
  options.accel_columns = {"fx", "fy", "fz"};
  options.accel_unit = SpecificForceUnit::kStandardGravity;
  options.temperature_column = "temp";
  const auto result = parse_imu_csv_text(text, options);
  ASSERT_EQ(result.samples.size(), 2u) << result.summary.describe_rejections("csv");
  const auto& first = result.samples[0];
  EXPECT_EQ(first.stamp_ns, 1000500000);
  EXPECT_DOUBLE_EQ(first.angular_rate_rad_s.x(), 1.0 * kDeg);
  EXPECT_DOUBLE_EQ(first.angular_rate_rad_s.y(), -2.0 * kDeg);
  EXPECT_DOUBLE_EQ(first.angular_rate_rad_s.z(), 0.5 * kDeg);
  EXPECT_DOUBLE_EQ(first.specific_force_m_s2.z(), kG);
  ASSERT_TRUE(first.temperature_c.has_value());
  EXPECT_DOUBLE_EQ(*first.temperature_c, 21.5);
  EXPECT_FALSE(result.samples[1].temperature_c.has_value());  // empty cell: no reading at this row
  EXPECT_DOUBLE_EQ(result.samples[1].angular_rate_rad_s.x(), M_PI / 2.0);
  EXPECT_DOUBLE_EQ(result.samples[1].specific_force_m_s2.x(), 0.5 * kG);
  EXPECT_DOUBLE_EQ(result.samples[1].specific_force_m_s2.y(), -kG);
  EXPECT_EQ(result.summary.rows_without_temperature, 1u);
  EXPECT_EQ(result.summary.header.size(), 8u);
  EXPECT_EQ(result.summary.first_stamp_ns, 1000500000);
  EXPECT_EQ(result.summary.last_stamp_ns, 1010500000);
}

TEST(CsvImuImport, EveryTimeUnitGivesTheSameStamp) {
  const std::pair<TimeUnit, std::string> cases[] = {
      {TimeUnit::kSecond, "1700000000.123456789"},      {TimeUnit::kMillisecond, "1700000000123.456789"},
      {TimeUnit::kMicrosecond, "1700000000123456.789"}, {TimeUnit::kNanosecond, "1700000000123456789"},
      {TimeUnit::kSecond, "1.700000000123456789e9"},    {TimeUnit::kMillisecond, "+1.700000000123456789E12"}};
  for (const auto& [unit, text] : cases) {
    CsvImportOptions options;
    options.has_header = false;
    options.time_unit = unit;
    const auto result = parse_imu_csv_text(text + ",0,0,0,0,0,9.8\n", options);
    ASSERT_EQ(result.samples.size(), 1u) << text;
    EXPECT_EQ(result.samples[0].stamp_ns, 1700000000123456789LL) << text;  // exact, no double rounding
  }
}

TEST(CsvImuImport, DecimalTimeParsingIsExactAndRefusesJunk) {
  EXPECT_EQ(parse_decimal_time_ns("0.0000000005", TimeUnit::kSecond), 1);  // half a ns rounds up
  EXPECT_EQ(parse_decimal_time_ns("0.0000000004999", TimeUnit::kSecond), 0);
  EXPECT_EQ(parse_decimal_time_ns("0.00000000000001", TimeUnit::kSecond), 0);
  EXPECT_EQ(parse_decimal_time_ns("-2", TimeUnit::kSecond), -2000000000LL);
  EXPECT_EQ(parse_decimal_time_ns("5.", TimeUnit::kMicrosecond), 5000);
  EXPECT_EQ(parse_decimal_time_ns(".5", TimeUnit::kMillisecond), 500000);
  EXPECT_EQ(parse_decimal_time_ns("0000.25", TimeUnit::kSecond), 250000000);
  EXPECT_EQ(parse_decimal_time_ns("2.5e-3", TimeUnit::kSecond), 2500000);
  EXPECT_EQ(parse_decimal_time_ns(" 7 ", TimeUnit::kNanosecond), 7);
  for (const char* junk : {"", ".", "-", "e5", "1e", "1e+", "1.2.3", "12abc", "nan", "inf", "0x10", "1e99999", "1 2",
                           "99999999999999999999", "1e30"}) {
    EXPECT_FALSE(parse_decimal_time_ns(junk, TimeUnit::kSecond).has_value()) << "'" << junk << "'";
  }
}

TEST(CsvImuImport, ReadsWithoutAHeaderByColumnNumber) {
  CsvImportOptions options;
  options.has_header = false;
  options.delimiter = '\t';
  options.time_column = "7";
  options.gyro_columns = {"1", "2", "3"};
  options.accel_columns = {"4", "5", "6"};
  const auto result = parse_imu_csv_text("0.1\t0.2\t0.3\t1\t2\t3\t10\n0.1\t0.2\t0.3\t1\t2\t3\t11\r\n", options);
  ASSERT_EQ(result.samples.size(), 2u);
  EXPECT_EQ(result.samples[1].stamp_ns, 11000000000LL);
  EXPECT_DOUBLE_EQ(result.samples[1].angular_rate_rad_s.z(), 0.3);
  EXPECT_DOUBLE_EQ(result.samples[1].specific_force_m_s2.z(), 3.0);  // CRLF line end tolerated
}

TEST(CsvImuImport, SkipsBlankAndCommentLinesAndAByteOrderMarkButCountsThemInLineNumbers) {
  const std::string text = "\xEF\xBB\xBF# logger v2\n" + kHeader + "\n1,0,0,0,0,0,1\n# pause\n2,x,0,0,0,0,1\n";
  const auto result = parse_imu_csv_text(text, plain());
  EXPECT_EQ(result.samples.size(), 1u);
  ASSERT_EQ(result.summary.rejected.size(), 1u);
  EXPECT_EQ(result.summary.rejected[0].line, 6u);
  EXPECT_EQ(result.summary.header[0], "t");
  EXPECT_EQ(result.summary.lines, 6u);
}

TEST(CsvImuImport, EveryKindOfBadRowIsRejectedWithItsLineAndReason) {
  const std::string text = kHeader +
                           "1,0,0,0,0,0,1\n"      // 2 good
                           "2,0,0,0,0,0\n"        // 3 too few fields
                           "3,0,0,0,0,0,1,9\n"    // 4 too many
                           "4,abc,0,0,0,0,1\n"    // 5 not a number
                           "5,0,NaN,0,0,0,1\n"    // 6 NaN
                           "6,0,0,inf,0,0,1\n"    // 7 infinite
                           "7,0,0,0,,0,1\n"       // 8 empty cell
                           "8,0,0,0,0,0,1\n"      // 9 good
                           "8,0,0,0,0,0,1\n"      // 10 same time
                           "7.5,0,0,0,0,0,1\n"    // 11 time goes back
                           "t9,0,0,0,0,0,1\n"     // 12 time not a number
                           "nan,0,0,0,0,0,1\n"    // 13 time NaN
                           "-1,0,0,0,0,0,1\n"     // 14 before the ROS epoch
                           "9,0,0,0,0,0,1e400\n"  // 15 overflows a double
                           "10,0,0,0,0,0,1\n";    // 16 good
  const auto result = parse_imu_csv_text(text, plain(), "log.csv");
  const auto& summary = result.summary;
  EXPECT_EQ(summary.accepted_rows, 3u);
  EXPECT_EQ(summary.rejected_row_count, 12u);
  EXPECT_EQ(rejection_lines(summary), "3 4 5 6 7 8 10 11 12 13 14 15 ");
  const auto reason = [&](std::size_t line) {
    for (const auto& row : summary.rejected) {
      if (row.line == line) return row.reason;
    }
    return std::string("(none)");
  };
  EXPECT_EQ(reason(3), "6 fields, expected 7 as in the header");
  EXPECT_EQ(reason(4), "8 fields, expected 7 as in the header");
  EXPECT_EQ(reason(5), "column 2 (gx): 'abc' is not a number");
  EXPECT_EQ(reason(6), "column 3 (gy): 'NaN' is not a finite number");
  EXPECT_EQ(reason(7), "column 4 (gz): 'inf' is not a finite number");
  EXPECT_EQ(reason(8), "column 5 (ax): is empty");
  EXPECT_EQ(reason(10), "time 8.000000000 s is not after the previous good row's 8.000000000 s");
  EXPECT_EQ(reason(11), "time 7.500000000 s is not after the previous good row's 8.000000000 s");
  EXPECT_EQ(reason(12), "column 1 (t): 't9' is not a time");
  EXPECT_EQ(reason(13), "column 1 (t): 'nan' is not a time");
  EXPECT_NE(reason(14).find("outside ROS time"), std::string::npos) << reason(14);
  EXPECT_NE(reason(15).find("'1e400' is not a"), std::string::npos) << reason(15);
  const std::string description = summary.describe_rejections("log.csv");
  EXPECT_EQ(description.substr(0, description.find('\n')), "log.csv: 12 bad rows of 15 data rows");
  EXPECT_NE(description.find("\n  line 5: column 2 (gx): 'abc' is not a number"), std::string::npos);
}

TEST(CsvImuImport, ReportsTheFirstRowsButCountsThemAll) {
  std::string text = kHeader;
  for (int i = 1; i <= 50; ++i) text += std::to_string(i) + (i % 2 ? ",0,0,0,0,0,1\n" : ",0,0,0,0,0,x\n");
  CsvImportOptions options;
  options.max_reported_rows = 5;
  const auto result = parse_imu_csv_text(text, options, "big.csv");
  EXPECT_EQ(result.summary.rejected_row_count, 25u);
  EXPECT_EQ(result.summary.rejected.size(), 5u);
  EXPECT_EQ(result.samples.size(), 25u);
  EXPECT_NE(result.summary.describe_rejections("big.csv").find("... and 20 more"), std::string::npos);
}

TEST(CsvImuImport, ASingleFieldRowSuggestsTheDelimiter) {
  const auto result = parse_imu_csv_text(kHeader + "1;0;0;0;0;0;1\n", plain());
  ASSERT_EQ(result.summary.rejected.size(), 1u);
  EXPECT_EQ(result.summary.rejected[0].reason, "1 field, expected 7 as in the header (is the delimiter ';'?)");
}

TEST(CsvImuImport, TemperatureCellsMayBeMissingButNotJunk) {
  CsvImportOptions options;
  options.temperature_column = "temp";
  const auto result = parse_imu_csv_text(
      "t,gx,gy,gz,ax,ay,az,temp\n1,0,0,0,0,0,1,20\n2,0,0,0,0,0,1,nan\n3,0,0,0,0,0,1,hot\n"
      "4,0,0,0,0,0,1,inf\n5,0,0,0,0,0,1,\n",
      options);
  EXPECT_EQ(result.samples.size(), 3u);
  EXPECT_EQ(result.summary.rows_without_temperature, 2u);
  EXPECT_EQ(rejection_lines(result.summary), "4 5 ");
}

TEST(CsvImuImport, TimeOffsetMovesTimeSinceBootIntoRosTime) {
  CsvImportOptions options;
  options.time_unit = TimeUnit::kMillisecond;
  const std::string text = kHeader + "0,0,0,0,0,0,1\n5,0,0,0,0,0,1\n";
  EXPECT_EQ(parse_imu_csv_text(text, options).summary.rejected_row_count, 1u);  // time zero is not a ROS stamp
  options.time_offset_ns = 1000000000;
  const auto result = parse_imu_csv_text(text, options);
  ASSERT_EQ(result.samples.size(), 2u);
  EXPECT_EQ(result.samples[0].stamp_ns, 1000000000);
  EXPECT_EQ(result.samples[1].stamp_ns, 1005000000);
}

TEST(CsvImuImport, AMappingThatDoesNotFitTheFileIsAConfigurationError) {
  const auto refuses = [](const std::string& text, const CsvImportOptions& options, const std::string& expected) {
    try {
      parse_imu_csv_text(text, options, "log.csv");
      ADD_FAILURE() << "accepted; expected: " << expected;
    } catch (const ConfigError& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
  };
  CsvImportOptions named;
  named.gyro_columns = {"gx", "gy", "gyro_z"};
  refuses(kHeader + "1,0,0,0,0,0,1\n", named,
          "log.csv: gyro_columns.z: no column 'gyro_z' in the header (it has: t, gx, gy, gz, ax, ay, az)");
  named.has_header = false;
  refuses("1,0,0,0,0,0,1\n", named, "is a name, but the file is read without a header line");
  refuses("1,0,0,0,0,0,1\n2,0,0,0,0,0,1\n", plain(), "log.csv: header: line 1 is numbers, not a header line");
  CsvImportOptions wide;
  wide.temperature_column = "9";
  refuses(kHeader + "1,0,0,0,0,0,1\n", wide, "column 9 is mapped, but the header has 7 fields");
  CsvImportOptions duplicate;
  duplicate.gyro_columns = {"gx", "2", "3"};
  refuses("t,gx,gx,gz,ax,ay,az\n1,0,0,0,0,0,1\n", duplicate, "the header names 'gx' twice");
  CsvImportOptions zero;
  zero.time_column = "0";
  refuses(kHeader + "1,0,0,0,0,0,1\n", zero, "column numbers start at 1");
  CsvImportOptions comma;
  comma.decimal_comma = true;
  refuses(kHeader + "1,0,0,0,0,0,1\n", comma, "decimal_comma: needs a delimiter other than ','");
}

TEST(CsvImuImport, AnEmptyFileIsBadData) {
  EXPECT_THROW(parse_imu_csv_text("", plain()), InputError);
  EXPECT_THROW(parse_imu_csv_text(kHeader + "\n# nothing logged\n", plain()), InputError);
}

TEST(CsvImuImport, UnitNamesAreCheckedAndNamedInTheMessage) {
  EXPECT_EQ(parse_time_unit("us", "f", "k"), TimeUnit::kMicrosecond);
  EXPECT_EQ(parse_angular_rate_unit("deg_s", "f", "k"), AngularRateUnit::kDegreePerSecond);
  EXPECT_EQ(parse_specific_force_unit("g", "f", "k"), SpecificForceUnit::kStandardGravity);
  EXPECT_EQ(parse_delimiter("tab", "f", "k"), '\t');
  EXPECT_EQ(parse_bad_row_policy("skip", "f", "k"), BadRowPolicy::kSkip);
  try {
    parse_angular_rate_unit("dps", "import_csv", "--gyro-unit");
    ADD_FAILURE();
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()), "import_csv: --gyro-unit: unknown angular-rate unit 'dps' (rad_s or deg_s)");
  }
  EXPECT_THROW(parse_time_unit("sec", "f", "k"), ConfigError);
  EXPECT_THROW(parse_specific_force_unit("mg", "f", "k"), ConfigError);
  EXPECT_THROW(parse_delimiter("|", "f", "k"), ConfigError);
  EXPECT_THROW(parse_bad_row_policy("ignore", "f", "k"), ConfigError);
}

// A line longer than kMaxLineBytes is a bad row read past without being kept (a 1 GiB line used
// to take 2.1 GB of memory); before the header it refuses the file.
TEST(CsvImuImport, AnOverlongLineIsABadRowAndIsNotKept) {
  const std::string text = kHeader + "1,0,0,0,0,0,1\n" + std::string(kMaxLineBytes + 1, '5') + "\n2,0,0,0,0,0,1\n";
  const auto result = parse_imu_csv_text(text, plain());
  EXPECT_EQ(result.samples.size(), 2u);
  ASSERT_EQ(result.summary.rejected.size(), 1u);
  EXPECT_EQ(result.summary.rejected[0].line, 3u);
  EXPECT_EQ(result.summary.rejected[0].reason.rfind("longer than 65536 bytes", 0), 0u)
      << result.summary.rejected[0].reason;
  const std::string exactly = kHeader + "1,0,0,0,0,0," + std::string(kMaxLineBytes - 13, '0') + "1\n";
  EXPECT_EQ(parse_imu_csv_text(exactly, plain()).samples.size(), 1u) << "a line of exactly the limit is read";
  EXPECT_THROW(parse_imu_csv_text(std::string(kMaxLineBytes + 10, 'x') + "\n1,0,0,0,0,0,1\n", plain()), InputError);
}

CsvImportOptions inferring() {
  CsvImportOptions options;
  options.infer_from_file = true;
  return options;
}

TEST(CsvImuImport, EurocAndOtherUnitCarryingHeadersAreRecognised) {
  const std::string euroc =
      "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],a_RS_S_x [m s^-2],"
      "a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]\n"
      "1403636579758555392,-0.099,0.14,0.025,8.11,-1.96,-2.60\n"
      "1403636579763555584,-0.098,0.14,0.026,8.13,-1.96,-2.60\n";
  const auto result = parse_imu_csv_text(euroc, inferring());
  ASSERT_EQ(result.samples.size(), 2u) << result.summary.describe_rejections("csv");
  EXPECT_EQ(result.samples[1].stamp_ns, 1403636579763555584LL);
  EXPECT_DOUBLE_EQ(result.samples[0].specific_force_m_s2.x(), 8.11);
  EXPECT_EQ(result.summary.recognised.rfind("EuRoC/ASL format: ", 0), 0u) << result.summary.recognised;
  EXPECT_EQ(result.summary.units, "time ns, gyro rad_s, accel m_s2");
  // Without inference (the parser's default) the '#' line is a comment, as it always was.
  EXPECT_THROW(parse_imu_csv_text(euroc, plain()), ConfigError);

  // Columns found by name in another order, units from brackets and suffixes, temperature by its unit.
  const std::string mixed =
      "ax (g),ay (g),az (g),stamp_ms,gx (deg/s),gy (deg/s),gz (deg/s),temperature_c\n"
      "0,0,1,1700000000000,90,0,0,21.5\n";
  const auto other = parse_imu_csv_text(mixed, inferring());
  ASSERT_EQ(other.samples.size(), 1u) << other.summary.describe_rejections("csv");
  EXPECT_EQ(other.samples[0].stamp_ns, 1700000000000000000LL);
  EXPECT_DOUBLE_EQ(other.samples[0].angular_rate_rad_s.x(), M_PI / 2.0);
  EXPECT_DOUBLE_EQ(other.samples[0].specific_force_m_s2.z(), kG);
  ASSERT_TRUE(other.samples[0].temperature_c.has_value());
  EXPECT_DOUBLE_EQ(*other.samples[0].temperature_c, 21.5);
  EXPECT_EQ(other.summary.units, "time ms, gyro deg_s, accel g");

  // export_csv's own header reads back with no options.
  CsvExportOptions export_options;
  export_options.with_temperature = true;
  const std::string exported = imu_csv_header(export_options) + "\n1700000000.25,0.1,0.2,0.3,1,2,9.8,25\n";
  const auto back = parse_imu_csv_text(exported, inferring());
  ASSERT_EQ(back.samples.size(), 1u);
  EXPECT_TRUE(back.samples[0].temperature_c.has_value());
}

TEST(CsvImuImport, AGivenUnitTheHeaderContradictsIsRefused) {
  CsvImportOptions options = inferring();
  options.gyro_unit = AngularRateUnit::kDegreePerSecond;
  options.given.gyro_unit = true;
  try {
    parse_imu_csv_text(
        "time_s,gyro_x_rad_s,gyro_y_rad_s,gyro_z_rad_s,accel_x_m_s2,accel_y_m_s2,accel_z_m_s2\n"
        "1700000000,0,0,0,0,0,9.8\n",
        options, "log.csv");
    ADD_FAILURE();
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "log.csv: gyro unit: 'deg_s' given, but the header names the gyro columns in rad_s");
  }
}

TEST(CsvImuImport, ARelativeTimeColumnIsOffsetUnlessAnOffsetIsGiven) {
  const std::string text = kHeader + "0,0,0,0,0,0,1\n0.01,0,0,0,0,0,1\n";
  const auto relative = parse_imu_csv_text(text, inferring());
  ASSERT_EQ(relative.samples.size(), 2u) << relative.summary.describe_rejections("csv");
  EXPECT_EQ(relative.samples[0].stamp_ns, 1'000'000'000LL * 1'000'000'000LL);
  EXPECT_EQ(relative.samples[1].stamp_ns - relative.samples[0].stamp_ns, 10'000'000);
  EXPECT_EQ(relative.summary.relative_time_offset_ns, 1'000'000'000LL * 1'000'000'000LL);
  CsvImportOptions given = inferring();
  given.time_offset_ns = 0;
  given.given.time_offset = true;
  const auto kept = parse_imu_csv_text(text, given);
  EXPECT_EQ(kept.summary.rejected_row_count, 1u) << "time 0 is still outside ROS time when asked for";
  const auto absolute = parse_imu_csv_text(kHeader + "1700000000,0,0,0,0,0,1\n", inferring());
  EXPECT_EQ(absolute.samples[0].stamp_ns, 1700000000LL * 1'000'000'000LL);
  EXPECT_EQ(absolute.summary.relative_time_offset_ns, 0);
}

TEST(CsvImportConfig, ReadsEveryKeyAndRefusesUnknownOnes) {
  const auto options = parse_csv_import_options(
      "delimiter: ';'\nheader: true\ndecimal_comma: true\n"
      "time: {column: t_ms, unit: ms, offset_s: 1700000000.5}\n"
      "gyro: {columns: [gx, gy, gz], unit: deg_s}\naccel: {columns: [4, 5, 6], unit: g}\n"
      "temperature: {column: temp_c}\n",
      "logger.yaml");
  EXPECT_EQ(options.delimiter, ';');
  EXPECT_TRUE(options.decimal_comma);
  EXPECT_EQ(options.time_column, "t_ms");
  EXPECT_EQ(options.time_unit, TimeUnit::kMillisecond);
  EXPECT_EQ(options.time_offset_ns, 1700000000500000000LL);
  EXPECT_EQ(options.gyro_columns[2], "gz");
  EXPECT_EQ(options.gyro_unit, AngularRateUnit::kDegreePerSecond);
  EXPECT_EQ(options.accel_columns[0], "4");
  EXPECT_EQ(options.accel_unit, SpecificForceUnit::kStandardGravity);
  EXPECT_EQ(options.temperature_column, "temp_c");
  const auto defaults = parse_csv_import_options("", "empty.yaml");
  EXPECT_EQ(defaults.time_column, "1");

  const auto refuses = [](const std::string& yaml, const std::string& expected) {
    try {
      parse_csv_import_options(yaml, "logger.yaml");
      ADD_FAILURE() << "accepted: " << yaml;
    } catch (const ConfigError& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
  };
  refuses("gyro: {colums: [a, b, c]}", "logger.yaml: gyro.colums: unknown key (known: columns, unit)");
  refuses("gyro: {columns: [a, b]}", "gyro.columns: must list three columns");
  refuses("accel: {unit: mg}", "logger.yaml: accel.unit: unknown specific-force unit 'mg'");
  refuses("time: {offset_s: soon}", "time.offset_s: 'soon' is not a number of seconds");
  refuses("header: maybe", "header: must be true or false");
  refuses("delimiter: '|'", "delimiter: unknown delimiter");
  refuses("[1, 2", "not valid YAML");
  refuses("- a\n- b\n", "(document): must be a mapping");
}

ImuCsvSample sample(std::int64_t stamp_ns, double base, std::optional<double> temperature_c) {
  ImuCsvSample s;
  s.stamp_ns = stamp_ns;
  s.angular_rate_rad_s = {base / 3.0, -base / 7.0, 1e-7 * base};
  s.specific_force_m_s2 = {0.1 / base, -9.80665 + base * 1e-3, std::sqrt(2.0) * base};
  s.temperature_c = temperature_c;
  return s;
}

std::string export_text(const std::vector<ImuCsvSample>& samples, const CsvExportOptions& options) {
  std::ostringstream out;
  out << imu_csv_header(options) << '\n';
  for (const auto& s : samples) write_imu_csv_row(out, s, options);
  return out.str();
}

TEST(CsvImuExport, HeaderNamesUnitsAndSiRoundTripsExactly) {
  CsvExportOptions options;
  options.with_temperature = true;
  EXPECT_EQ(imu_csv_header(options),
            "time_s,gyro_x_rad_s,gyro_y_rad_s,gyro_z_rad_s,accel_x_m_s2,accel_y_m_s2,accel_z_m_s2,temperature_c");
  const std::vector<ImuCsvSample> samples = {sample(1700000000000000001LL, 1.0, 20.125),
                                             sample(1700000000005000001LL, 2.0, std::nullopt),
                                             sample(1700000000010000001LL, 3.0, -5.0 / 3.0)};
  const std::string text = export_text(samples, options);
  EXPECT_NE(text.find("\n1700000000.000000001,"), std::string::npos) << text;
  EXPECT_NE(text.find(",\n1700000000.010000001,"), std::string::npos) << "empty temperature cell: " << text;
  // The import defaults read the export's column order; names work too.
  CsvImportOptions by_position;
  by_position.temperature_column = "8";
  for (const auto& import : {import_options_for(options), by_position}) {
    const auto back = parse_imu_csv_text(text, import);
    ASSERT_EQ(back.samples.size(), samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      EXPECT_EQ(back.samples[i].stamp_ns, samples[i].stamp_ns);
      EXPECT_EQ(back.samples[i].angular_rate_rad_s, samples[i].angular_rate_rad_s);  // bit for bit
      EXPECT_EQ(back.samples[i].specific_force_m_s2, samples[i].specific_force_m_s2);
      EXPECT_EQ(back.samples[i].temperature_c, samples[i].temperature_c);
    }
  }
}

TEST(CsvImuExport, FieldUnitsAndOtherDelimitersReadBackWithinRounding) {
  CsvExportOptions options;
  options.delimiter = '\t';
  options.gyro_unit = AngularRateUnit::kDegreePerSecond;
  options.accel_unit = SpecificForceUnit::kStandardGravity;
  EXPECT_EQ(imu_csv_header(options),
            "time_s\tgyro_x_deg_s\tgyro_y_deg_s\tgyro_z_deg_s\taccel_x_g\taccel_y_g\taccel_z_g");
  const std::vector<ImuCsvSample> samples = {sample(2000000000, 1.0, std::nullopt),
                                             sample(3000000000, 5.0, std::nullopt)};
  const std::string text = export_text(samples, options);
  EXPECT_NE(text.find("\t-0.999898"), std::string::npos) << "accel y of the first sample is about -1 g: " << text;
  const auto back = parse_imu_csv_text(text, import_options_for(options));
  ASSERT_EQ(back.samples.size(), 2u);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    EXPECT_EQ(back.samples[i].stamp_ns, samples[i].stamp_ns);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(back.samples[i].angular_rate_rad_s[axis], samples[i].angular_rate_rad_s[axis],
                  1e-15 * std::abs(samples[i].angular_rate_rad_s[axis]));
      EXPECT_NEAR(back.samples[i].specific_force_m_s2[axis], samples[i].specific_force_m_s2[axis],
                  1e-15 * std::abs(samples[i].specific_force_m_s2[axis]));
    }
  }
}

}  // namespace
