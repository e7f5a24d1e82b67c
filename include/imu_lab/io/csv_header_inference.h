// What a CSV header tells about its columns when its names carry units, so that import_csv reads
// such files with no options: EuRoC/ASL's "#timestamp [ns],w_RS_S_x [rad s^-1],...,a_RS_S_z
// [m s^-2]" (the de-facto format of IMU logs in robotics datasets), export_csv's own
// "time_s,gyro_x_rad_s,...,accel_z_m_s2,temperature_c", and names like "gx (deg/s)".
// A unit is read from brackets ("[ns]", "(deg/s)") or a suffix ("_ms", "_rad_s", "_m_s2", "_g",
// "_c"); a column's role from its name (time/timestamp/stamp; w, gyro, gyr, omega,
// angular_velocity + x/y/z; a, acc, accel, linear_acceleration + x/y/z; temperature/temp) or its
// unit. What the user gave (CsvImportOptions::given) is kept; a given unit the header contradicts
// is refused, since one of the two is wrong.
#pragma once

#include <string>
#include <vector>

#include "imu_lab/io/csv_imu_import.h"

namespace imu_lab {
namespace io {

struct HeaderInference {
  CsvImportOptions options;  // the input options with what the header decided filled in
  std::string description;   // what was recognised, for the summary; empty when nothing was
};

// `header`: the header line's fields (a leading '#' on the first already removed). Throws
// ConfigError (naming `source` and the option) when a given unit contradicts the header.
HeaderInference infer_from_header(const std::vector<std::string>& header, const CsvImportOptions& options,
                                  const std::string& source);

}  // namespace io
}  // namespace imu_lab
