// The column mapping of a logger's CSV as a small YAML file, so one file describes one logger:
//
//   delimiter: ";"            # ",", ";" or tab
//   header: true              # the first line names the columns
//   decimal_comma: false      # "0,25" means 0.25
//   time: {column: t_ms, unit: ms, offset_s: 0}
//   gyro: {columns: [gx, gy, gz], unit: deg_s}      # rad_s or deg_s
//   accel: {columns: [ax, ay, az], unit: g}         # m_s2 or g (9.80665 m/s^2)
//   temperature: {column: temp_c}                   # optional, degC
//
// Columns are header names or 1-based numbers. Every key is optional (the defaults of
// CsvImportOptions stay); an unknown key is a ConfigError, so a typo is never ignored.
#pragma once

#include <string>

#include "imu_lab/io/csv_imu_import.h"

namespace imu_lab {
namespace io {

// Throws ConfigError naming the file and the dotted key.
CsvImportOptions load_csv_import_options(const std::string& path, const CsvImportOptions& defaults = {});
CsvImportOptions parse_csv_import_options(const std::string& yaml_text, const std::string& source,
                                          const CsvImportOptions& defaults = {});

}  // namespace io
}  // namespace imu_lab
