// Writing IMU samples as CSV for people who analyse elsewhere: one header line naming each
// column with its unit (time_s, gyro_x_rad_s ... accel_z_m_s2, temperature_c), then one row per
// sample. Stamps are exact decimal seconds (9 digits), values print as the shortest text that
// reads back as the same double, so reading the file back (csv_imu_import.h, whose default column order is this one)
// gives the same doubles in SI.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

#include "imu_lab/io/csv_imu_import.h"

namespace imu_lab {
namespace io {

struct CsvExportOptions {
  char delimiter = ',';
  AngularRateUnit gyro_unit = AngularRateUnit::kRadPerSecond;
  SpecificForceUnit accel_unit = SpecificForceUnit::kMeterPerSecondSquared;
  bool with_temperature = false;  // an 8th column; empty where a sample has no reading
  // Taken off every stamp: the offset an import added (csv_imu_import.h's time_offset_ns, or its
  // relative_time_offset_ns for a relative time column), so the same number gives the file's
  // times back. 0: the stamps as they are.
  std::int64_t time_offset_ns = 0;
};

// The header line, without the newline.
std::string imu_csv_header(const CsvExportOptions& options);
// Throws InputError when a stamp minus the time offset is beyond int64 nanoseconds.
void write_imu_csv_row(std::ostream& out, const ImuCsvSample& sample, const CsvExportOptions& options);

// The import options that read a file written with `options` back (by the header's names).
CsvImportOptions import_options_for(const CsvExportOptions& options);

}  // namespace io
}  // namespace imu_lab
