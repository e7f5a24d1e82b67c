// Parsing an IMU logger's CSV (time, three rates, three specific forces, optionally a
// temperature) into SI samples with exact nanosecond stamps. ROS-free and pure over a stream, so
// the import tool, the tests and the fuzzer share it. Every row that cannot be used is reported
// with its line number and why; nothing is dropped silently.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace imu_lab {
namespace io {

enum class AngularRateUnit { kRadPerSecond, kDegreePerSecond };
enum class SpecificForceUnit { kMeterPerSecondSquared, kStandardGravity };  // g = 9.80665 m/s^2
enum class TimeUnit { kSecond, kMillisecond, kMicrosecond, kNanosecond };
enum class BadRowPolicy { kRefuse, kSkip };

// Unit names as users write them ("rad_s", "deg_s", "m_s2", "g", "s", "ms", "us", "ns",
// "refuse", "skip"); anything else -> ConfigError naming `source`, `key` and the accepted names.
AngularRateUnit parse_angular_rate_unit(const std::string& name, const std::string& source, const std::string& key);
SpecificForceUnit parse_specific_force_unit(const std::string& name, const std::string& source, const std::string& key);
TimeUnit parse_time_unit(const std::string& name, const std::string& source, const std::string& key);
BadRowPolicy parse_bad_row_policy(const std::string& name, const std::string& source, const std::string& key);
// "," ";" "tab" (or a literal tab) -> the character.
char parse_delimiter(const std::string& name, const std::string& source, const std::string& key);
// A time offset in seconds as exact decimal text -> nanoseconds; text that is not a number, or
// one beyond what int64 nanoseconds hold (+-9.2e9 s) -> ConfigError naming `source` and `key`.
std::int64_t parse_time_offset_ns(const std::string& text, const std::string& source, const std::string& key);
std::string unit_name(AngularRateUnit unit);
std::string unit_name(SpecificForceUnit unit);

// SI value of one unit.
double to_rad_s(AngularRateUnit unit);
double to_m_s2(SpecificForceUnit unit);

// One IMU sample, SI, stamp exact in nanoseconds since the epoch of the file's time column.
struct ImuCsvSample {
  std::int64_t stamp_ns = 0;
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();
  std::optional<double> temperature_c;  // empty: no column, or an empty / NaN cell in it
};

// A column: a header name, or a 1-based number ("1" is the first column). Numbers work without
// a header line; names need one.
struct CsvImportOptions {
  char delimiter = ',';
  bool has_header = true;
  bool decimal_comma = false;  // "0,25" means 0.25 (only with a delimiter other than ',')
  std::string time_column = "1";
  std::array<std::string, 3> gyro_columns{"2", "3", "4"};
  std::array<std::string, 3> accel_columns{"5", "6", "7"};
  std::string temperature_column;  // empty: no temperature
  TimeUnit time_unit = TimeUnit::kSecond;
  AngularRateUnit gyro_unit = AngularRateUnit::kRadPerSecond;
  SpecificForceUnit accel_unit = SpecificForceUnit::kMeterPerSecondSquared;
  std::int64_t time_offset_ns = 0;  // added to every stamp (e.g. to move time-since-boot to an epoch)
  BadRowPolicy bad_rows = BadRowPolicy::kRefuse;
  std::size_t max_reported_rows = 20;  // rejected rows kept with their reasons; all are counted

  // What the user set (options or the mapping file), for infer_from_header.
  struct Given {
    bool columns = false;  // any of time, gyro, accel columns
    bool time_unit = false, gyro_unit = false, accel_unit = false, temperature_column = false, time_offset = false;
  } given;
  // import_csv reads what the options leave open from the file: units and columns from a header
  // whose names carry them (csv_header_inference.h; a header line may then start with '#', as
  // EuRoC's does), and a relative time column (below kRelativeTimeLimit_s, i.e. time since power-up
  // or since the log's start, which ROS time cannot hold) moved by relative_time_offset_ns unless
  // an offset was given. Both are said in the summary. Off: the file is read as the options say.
  bool infer_from_file = false;
  std::int64_t relative_time_offset_ns = 1000000000LL * 1000000000LL;  // 1e9 s (2001-09-09), as emulate's default start
};

// A time column whose first time is below this reads as relative (about three years in seconds;
// an absolute clock reads over 1e9 s since 2001).
constexpr double kRelativeTimeLimit_s = 1e8;
// Longer lines are bad rows, read past without being kept (a damaged or binary file must not fill
// the memory: one 1 GiB line used to take 2.1 GB).
constexpr std::size_t kMaxLineBytes = 65536;

struct RejectedRow {
  std::size_t line = 0;  // 1-based line of the file
  std::string reason;
};

struct CsvImportSummary {
  std::size_t lines = 0;  // lines read, header, blank and comment lines included
  std::size_t accepted_rows = 0;
  std::size_t rejected_row_count = 0;        // every bad row
  std::vector<RejectedRow> rejected;         // the first max_reported_rows of them
  std::size_t rows_without_temperature = 0;  // with a temperature column: empty or NaN cells
  std::int64_t first_stamp_ns = 0, last_stamp_ns = 0;
  std::vector<std::string> header;           // the header's names, if there was one
  std::string recognised;                    // with infer_from_file: what the header told, or ""
  std::string units;                         // as read: "time ns, gyro rad_s, accel m_s2"
  std::string temperature_column;            // as read: "" for none
  std::int64_t relative_time_offset_ns = 0;  // with infer_from_file: added to a relative time column, or 0

  // "N bad rows of M: line 7: ...; line 9: ..." (capped as stored), for messages.
  std::string describe_rejections(const std::string& source) const;
};

// Reads `in` to the end, calling on_sample for each accepted row in file order. `source` names
// the input in messages. A mapping that does not fit the file (a named column the header lacks,
// a column beyond the row, a header expected but the first line is numbers) -> ConfigError.
// Bad rows are collected in the summary whatever the policy (the caller decides what refusal
// means); blank lines and lines starting with '#' are skipped. Rows: wrong field count, a cell
// that is not a finite number, a time before the previous accepted row's or out of the ROS time
// range, a line longer than kMaxLineBytes. Stamps are parsed from the decimal text exactly (no double rounding at 1e9
// s).
CsvImportSummary parse_imu_csv(std::istream& in, const CsvImportOptions& options, const std::string& source,
                               const std::function<void(const ImuCsvSample&)>& on_sample);

// The same over a string, collecting the samples (tests, fuzzing).
struct CsvImportResult {
  CsvImportSummary summary;
  std::vector<ImuCsvSample> samples;
};
CsvImportResult parse_imu_csv_text(const std::string& text, const CsvImportOptions& options,
                                   const std::string& source = "csv");

// Exact decimal text -> integer nanoseconds in `unit` ("1700000000.123456789" s, "1.5e3" ms,
// "-2"); rounds to the nearest ns. Empty on anything else or on overflow of int64.
std::optional<std::int64_t> parse_decimal_time_ns(const std::string& text, TimeUnit unit);

}  // namespace io
}  // namespace imu_lab
