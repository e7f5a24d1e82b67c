// import_csv: an IMU logger's CSV -> bag of sensor_msgs/Imu (and sensor_msgs/Temperature when a
// temperature column is mapped), SI, stamped from the file's time column. Columns by name or
// number, from options or a small YAML (io/csv_import_config.h). Bad rows are listed with their
// line numbers; by default any bad row refuses the whole file (exit 1, no bag), since a damaged
// log deserves a look before its noise is characterised; --on-bad-row skip imports the rest.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/io/csv_import_config.h"
#include "imu_lab/ros_io/bag/imu_csv_bag.h"

namespace {

constexpr const char* kTool = "import_csv";
constexpr const char* kCommandLine = "command line";

struct CommandLine {
  std::string csv_path, out_path, config_path;
  std::string delimiter, time_column, time_unit, gyro_unit, accel_unit, temperature_column, on_bad_row = "refuse";
  std::vector<std::string> gyro_columns, accel_columns;
  std::string time_offset_s;
  bool no_header = false, decimal_comma = false;
  std::size_t max_reported_rows = 20;
  imu_lab::ros_io::CsvBagTopics topics;
};

std::array<std::string, 3> triad(const std::vector<std::string>& columns, const std::string& option) {
  if (columns.size() != 3) throw imu_lab::ConfigError(kCommandLine, option, "needs three columns (x,y,z)");
  return {columns[0], columns[1], columns[2]};
}

// The YAML (if any) first, then each option given on the command line over it.
imu_lab::io::CsvImportOptions import_options(const CommandLine& c) {
  using namespace imu_lab::io;
  CsvImportOptions options = c.config_path.empty() ? CsvImportOptions{} : load_csv_import_options(c.config_path);
  options.infer_from_file = true;  // what the options leave open, from the header and the time column
  if (!c.delimiter.empty()) options.delimiter = parse_delimiter(c.delimiter, kCommandLine, "--delimiter");
  if (c.no_header) options.has_header = false;
  if (c.decimal_comma) options.decimal_comma = true;
  if (!c.time_column.empty()) options.time_column = c.time_column;
  if (!c.time_unit.empty()) options.time_unit = parse_time_unit(c.time_unit, kCommandLine, "--time-unit");
  options.given.columns |= !c.time_column.empty() || !c.gyro_columns.empty() || !c.accel_columns.empty();
  options.given.time_unit |= !c.time_unit.empty();
  options.given.gyro_unit |= !c.gyro_unit.empty();
  options.given.accel_unit |= !c.accel_unit.empty();
  options.given.temperature_column |= !c.temperature_column.empty();
  options.given.time_offset |= !c.time_offset_s.empty();
  if (!c.time_offset_s.empty())
    options.time_offset_ns = parse_time_offset_ns(c.time_offset_s, kCommandLine, "--time-offset-s");
  if (!c.gyro_columns.empty()) options.gyro_columns = triad(c.gyro_columns, "--gyro-columns");
  if (!c.accel_columns.empty()) options.accel_columns = triad(c.accel_columns, "--accel-columns");
  if (!c.gyro_unit.empty()) options.gyro_unit = parse_angular_rate_unit(c.gyro_unit, kCommandLine, "--gyro-unit");
  if (!c.accel_unit.empty()) options.accel_unit = parse_specific_force_unit(c.accel_unit, kCommandLine, "--accel-unit");
  if (!c.temperature_column.empty()) options.temperature_column = c.temperature_column;
  options.bad_rows = parse_bad_row_policy(c.on_bad_row, kCommandLine, "--on-bad-row");
  options.max_reported_rows = c.max_reported_rows;
  return options;
}

// What --time-offset-s can be instead for a file starting at file_start_ns: ROS time starts after
// 0 s, so 0 keeps the file's times only when they start above 0 (issue 46).
std::string other_offset_hint(std::int64_t file_start_ns) {
  if (file_start_ns > 0) return "--time-offset-s gives another offset, 0 keeps the file's times";
  const std::int64_t smallest_whole_s = -file_start_ns / 1000000000 + 1;  // the first whole second above -start
  return "--time-offset-s gives another offset, above " + imu_lab::format_stamp_s(-file_start_ns) +
         " s since ROS time starts after 0 s, e.g. --time-offset-s " + std::to_string(smallest_whole_s);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Import an IMU logger's CSV into a bag of sensor_msgs/Imu (+ sensor_msgs/Temperature)."};
  CommandLine c;
  app.add_option("csv", c.csv_path, "CSV file to read")->required();
  app.add_option("-o,--out", c.out_path, "bag to write")->required();
  app.add_option("--config", c.config_path, "column-mapping YAML (options given here override it)");
  app.add_option("--delimiter", c.delimiter, "',' ';' or tab (default ',')");
  app.add_flag("--no-header", c.no_header, "the first line is data (columns must be numbers)");
  app.add_flag("--decimal-comma", c.decimal_comma, "numbers are written 0,25 (needs --delimiter ';' or tab)");
  app.add_option("--time-column", c.time_column, "time column: header name or 1-based number (default 1)");
  app.add_option("--time-unit", c.time_unit, "s, ms, us or ns (default s)");
  app.add_option("--time-offset-s", c.time_offset_s, "added to every stamp, e.g. to move time since boot to an epoch");
  app.add_option("--gyro-columns", c.gyro_columns, "x,y,z rate columns (default 2,3,4)")->delimiter(',');
  app.add_option("--gyro-unit", c.gyro_unit, "rad_s or deg_s (default rad_s)");
  app.add_option("--accel-columns", c.accel_columns, "x,y,z specific-force columns (default 5,6,7)")->delimiter(',');
  app.add_option("--accel-unit", c.accel_unit, "m_s2 or g (9.80665 m/s^2; default m_s2)");
  app.add_option("--temperature-column", c.temperature_column, "temperature column in degC (default: none)");
  app.add_option("--on-bad-row", c.on_bad_row, "refuse: any bad row writes nothing; skip: import the good rows")
      ->capture_default_str();
  app.add_option("--max-reported-rows", c.max_reported_rows, "bad rows listed (all are counted)")
      ->capture_default_str();
  app.add_option("--imu-topic", c.topics.imu, "sensor_msgs/Imu topic")->capture_default_str();
  app.add_option("--temperature-topic", c.topics.temperature, "sensor_msgs/Temperature topic")->capture_default_str();
  app.add_option("--frame-id", c.topics.frame_id, "frame_id of the messages")->capture_default_str();
  if (const auto status = imu_lab::parse_tool_options("import_csv", app, argc, argv)) return *status;

  const imu_lab::ToolInput input{"CSV file", c.csv_path, ""};
  return imu_lab::run_tool_main(kTool, input, [&] {
    const auto options = import_options(c);
    const auto report = imu_lab::ros_io::import_csv_to_bag(c.csv_path, options, c.topics, c.out_path);
    const auto& summary = report.summary;
    if (summary.rejected_row_count > 0) {  // only reached when skipping
      std::cerr << kTool << ": skipped " << summary.describe_rejections(c.csv_path) << "\n";
    }
    const double span_s = 1e-9 * static_cast<double>(summary.last_stamp_ns - summary.first_stamp_ns);
    if (!summary.recognised.empty()) std::printf("%s: %s: %s\n", kTool, c.csv_path.c_str(), summary.recognised.c_str());
    if (summary.relative_time_offset_ns != 0) {
      using imu_lab::format_stamp_s;
      const std::int64_t file_start_ns = summary.first_stamp_ns - summary.relative_time_offset_ns;
      std::printf(
          "%s: %s: the time column is relative (it starts at %s s, before any epoch ROS time can hold): "
          "%s s added to every stamp (%s; export_csv --time-offset-s %s takes it off again)\n",
          kTool, c.csv_path.c_str(), format_stamp_s(file_start_ns).c_str(),
          format_stamp_s(summary.relative_time_offset_ns).c_str(), other_offset_hint(file_start_ns).c_str(),
          format_stamp_s(summary.relative_time_offset_ns).c_str());
    }
    std::printf("%s: wrote %s: %zu samples on %s (%s), %.3f s", kTool, c.out_path.c_str(), summary.accepted_rows,
                c.topics.imu.c_str(), summary.units.c_str(), span_s);
    if (summary.accepted_rows > 1)
      std::printf(" at %.6g Hz mean", static_cast<double>(summary.accepted_rows - 1) / span_s);
    if (!summary.temperature_column.empty()) {
      std::printf(", %zu temperatures on %s (%zu rows without one)", report.temperature_messages,
                  c.topics.temperature.c_str(), summary.rows_without_temperature);
    }
    if (summary.rejected_row_count > 0) {
      std::printf("; %zu bad rows skipped\n", summary.rejected_row_count);
    } else {
      std::printf("; no bad rows\n");
    }
    return 0;
  });
}
