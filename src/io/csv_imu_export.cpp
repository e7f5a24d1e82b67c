#include "imu_lab/io/csv_imu_export.h"

#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <string_view>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace io {
namespace {

const char* const kAxes[] = {"x", "y", "z"};

std::string gyro_column(int axis, const CsvExportOptions& options) {
  return std::string("gyro_") + kAxes[axis] + "_" + unit_name(options.gyro_unit);
}

std::string accel_column(int axis, const CsvExportOptions& options) {
  return std::string("accel_") + kAxes[axis] + "_" + unit_name(options.accel_unit);
}

const char* const kTimeColumn = "time_s";
const char* const kTemperatureColumn = "temperature_c";

// The shortest text that reads back as the same double (9.8, not 9.8000000000000007).
void write_value(std::ostream& out, char delimiter, double value) {
  char text[32];
  const auto written = std::to_chars(text, text + sizeof text, value);
  out << delimiter << std::string_view(text, static_cast<std::size_t>(written.ptr - text));
}

}  // namespace

std::string imu_csv_header(const CsvExportOptions& options) {
  std::string header = kTimeColumn;
  for (int axis = 0; axis < 3; ++axis) header += options.delimiter + gyro_column(axis, options);
  for (int axis = 0; axis < 3; ++axis) header += options.delimiter + accel_column(axis, options);
  if (options.with_temperature) header += options.delimiter + std::string(kTemperatureColumn);
  return header;
}

void write_imu_csv_row(std::ostream& out, const ImuCsvSample& sample, const CsvExportOptions& options) {
  std::int64_t time_ns = 0;
  if (__builtin_sub_overflow(sample.stamp_ns, options.time_offset_ns, &time_ns)) {
    throw InputError("stamp " + format_stamp_s(sample.stamp_ns) + " s minus the time offset " +
                     format_stamp_s(options.time_offset_ns) + " s is beyond +-9.2e9 s (stamps are int64 ns)");
  }
  const std::int64_t seconds = time_ns / 1000000000;
  const std::int64_t nanoseconds = time_ns % 1000000000;
  char stamp[48];
  if (time_ns < 0) {
    std::snprintf(stamp, sizeof stamp, "-%" PRId64 ".%09" PRId64, -seconds, -nanoseconds);
  } else {
    std::snprintf(stamp, sizeof stamp, "%" PRId64 ".%09" PRId64, seconds, nanoseconds);
  }
  out << stamp;
  const double gyro_per_si = 1.0 / to_rad_s(options.gyro_unit);
  const double accel_per_si = 1.0 / to_m_s2(options.accel_unit);
  for (int axis = 0; axis < 3; ++axis)
    write_value(out, options.delimiter, sample.angular_rate_rad_s[axis] * gyro_per_si);
  for (int axis = 0; axis < 3; ++axis) {
    write_value(out, options.delimiter, sample.specific_force_m_s2[axis] * accel_per_si);
  }
  if (options.with_temperature) {
    if (sample.temperature_c) {
      write_value(out, options.delimiter, *sample.temperature_c);
    } else {
      out << options.delimiter;  // no reading at this stamp: an empty cell
    }
  }
  out << '\n';
}

CsvImportOptions import_options_for(const CsvExportOptions& options) {
  CsvImportOptions import;
  import.delimiter = options.delimiter;
  import.has_header = true;
  import.time_column = kTimeColumn;
  import.time_unit = TimeUnit::kSecond;
  for (int axis = 0; axis < 3; ++axis) {
    import.gyro_columns[axis] = gyro_column(axis, options);
    import.accel_columns[axis] = accel_column(axis, options);
  }
  import.gyro_unit = options.gyro_unit;
  import.accel_unit = options.accel_unit;
  if (options.with_temperature) import.temperature_column = kTemperatureColumn;
  return import;
}

}  // namespace io
}  // namespace imu_lab
