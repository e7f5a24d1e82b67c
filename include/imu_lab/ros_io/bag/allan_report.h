// The report files of an Allan run, shared by the allan tool and the allan_monitor node:
//   DIR/<statistic>.csv for the nine statistics (oadev.csv, adev.csv, mdev.csv, ohdev.csv,
//   hdev.csv, tdev.csv, totdev.csv, akdev.csv, hkdev.csv; io/stability_table.h's format,
//   channels gyro_x..accel_z in rad_s and m_s2), DIR/allan_summary.yaml (allan_summary.h) and
//   DIR/allan.png (scripts/plot_allan.py, OADEV, with the fitted model's partial curves), and,
//   unless identification is off, the noise identification's files (allan_noise_report.h: noise.yaml,
//   kalibr_imu.yaml, kalibr_imu_chain.yaml, the partial curves), and,
//   when the run removed a warm-up first, DIR/warm_up.yaml (allan_warm_up.h).
//   The data files are one set, moved in together (atomic_file.h); allan.png is drawn from them
//   after that, and written atomically on its own. DIR is created.
#pragma once

#include <string>
#include <vector>

#include "imu_lab/io/stability_table.h"
#include "imu_lab/pipeline/allan_noise_report.h"
#include "imu_lab/pipeline/allan_summary.h"

namespace imu_lab {
namespace ros_io {

struct AllanReportFiles {
  std::vector<std::string> written;  // paths, in the order written
  std::string plot_problem;          // empty when the plot was written (or not asked for)
  pipeline::AllanNoiseReport noise;  // the identified triads and what went wrong identifying them
};

// The six channels' curves of one statistic, named and with units for the CSV.
std::vector<io::ChannelCurve> channel_curves(const allan::StreamingSnapshot& snapshot, allan::Statistic statistic);

// Throws std::runtime_error naming the file when a data file cannot be written. A failed plot
// (no python3/matplotlib) is reported in plot_problem only: the numbers are the report. A failed
// identification is reported in noise.problems and in allan_summary.yaml; the curves are kept.
AllanReportFiles write_allan_report(const std::string& directory, const pipeline::AllanRunDescription& run,
                                    const allan::StreamingSnapshot& snapshot, bool plot,
                                    const pipeline::AllanIdentifyOptions& identify = pipeline::AllanIdentifyOptions());

}  // namespace ros_io
}  // namespace imu_lab
