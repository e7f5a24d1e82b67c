// Helpers for the allan tool's tests: synthetic IMU bags with chosen stamps and values, and the
// tool's summary file.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "imu_lab/pipeline/allan_samples.h"

namespace imu_lab {
namespace test_support {

// `count` samples of white noise (gyro ~1e-3 rad/s, accel ~1e-2 m/s^2 about gravity on z),
// stamped every interval_ns from start_ns; the same seed gives the same samples.
std::vector<pipeline::AllanSample> white_noise_samples(std::size_t count, std::int64_t interval_ns, unsigned seed,
                                                       std::int64_t start_ns = 1'000'000'000'000'000'000LL);

// A knock at sample `knock_index` of white_noise_samples: accelerometer z rings at 200 times its
// noise (2 m/s^2 against 0.01), decaying over a tenth of a second at 12 Hz, and keeps a bias step of
// 0.005 m/s^2 after it.
void add_knock(std::vector<pipeline::AllanSample>& samples, std::size_t knock_index);

// Writes the samples as sensor_msgs/Imu messages on `topic`, each recorded at its stamp.
void write_imu_bag(const std::string& path, const std::vector<pipeline::AllanSample>& samples,
                   const std::string& topic = "/imu/raw");

struct ImuBagLayout {
  std::vector<std::string> imu_topics = {"/imu/raw"};  // every sample on each of them
  bool with_temperature = false;  // sensor_msgs/Temperature at 25 degC on /imu/temperature, every tenth stamp
  // A triad marked as not provided (covariance[0] = -1, values 0), as a driver of an IMU without it
  // publishes sensor_msgs/Imu.
  bool without_angular_rate = false;
  bool without_specific_force = false;
};
void write_imu_bag(const std::string& path, const std::vector<pipeline::AllanSample>& samples,
                   const ImuBagLayout& layout);

YAML::Node read_allan_summary(const std::string& report_directory);

// A numeric CSV with a header line (the tools' curve and partial-curve files).
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;  // one value per cell, in header order
  bool has_column(const std::string& name) const;
  std::vector<double> column(const std::string& name) const;  // throws std::out_of_range naming it when absent
};
// Throws std::runtime_error naming the file and the cell when a cell is not a number.
CsvTable read_csv_table(const std::string& path);

}  // namespace test_support
}  // namespace imu_lab
