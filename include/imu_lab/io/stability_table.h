// The CSV form of stability curves: one file per statistic, one row per tau, and for each
// channel its deviation, chi-squared bounds, EDF, number of terms and noise-type estimate.
// Column names carry the unit (gyro_x_dev_rad_s, accel_y_lo_m_s2, ...).
#pragma once

#include <string>
#include <vector>

#include "imu_lab/allan/batch.h"

namespace imu_lab {
namespace io {

struct ChannelCurve {
  std::string name;  // gyro_x ... accel_z
  std::string unit;  // rad_s, m_s2 (deviation unit, as it appears in column names)
  std::vector<allan::StabilityPoint> points;
};

// Rows follow the union of all channels' taus in increasing order; a channel without a point at
// a tau leaves its cells empty.
std::string format_stability_csv(const std::vector<ChannelCurve>& channels);

// Writes format_stability_csv() atomically.
void write_stability_csv(const std::string& path, const std::vector<ChannelCurve>& channels);

// Parses what format_stability_csv() wrote (for tests and for tools that compare runs).
std::vector<ChannelCurve> parse_stability_csv(const std::string& text);

}  // namespace io
}  // namespace imu_lab
