#include "allan_test_support.h"

#include <rosbag/bag.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

namespace imu_lab {
namespace test_support {

std::vector<pipeline::AllanSample> white_noise_samples(std::size_t count, std::int64_t interval_ns, unsigned seed,
                                                       std::int64_t start_ns) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<pipeline::AllanSample> samples(count);
  for (std::size_t i = 0; i < count; ++i) {
    samples[i].stamp_ns = start_ns + static_cast<std::int64_t>(i) * interval_ns;
    for (std::size_t c = 0; c < 3; ++c) samples[i].values[c] = 1e-3 * normal(generator);
    for (std::size_t c = 3; c < 6; ++c) samples[i].values[c] = (c == 5 ? 9.81 : 0.0) + 1e-2 * normal(generator);
  }
  return samples;
}

void add_knock(std::vector<pipeline::AllanSample>& samples, std::size_t knock_index) {
  for (std::size_t k = knock_index; k < samples.size(); ++k) {
    const double t = 1e-9 * static_cast<double>(samples[k].stamp_ns - samples[knock_index].stamp_ns);
    samples[k].values[5] += 0.005 + 2.0 * std::exp(-t / 0.1) * std::cos(2.0 * M_PI * 12.0 * t);
  }
}

void write_imu_bag(const std::string& path, const std::vector<pipeline::AllanSample>& samples,
                   const std::string& topic) {
  ImuBagLayout layout;
  layout.imu_topics = {topic};
  write_imu_bag(path, samples, layout);
}

void write_imu_bag(const std::string& path, const std::vector<pipeline::AllanSample>& samples,
                   const ImuBagLayout& layout) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  std::int64_t record_ns = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto& sample = samples[i];
    sensor_msgs::Imu imu;
    imu.header.stamp.fromNSec(static_cast<std::uint64_t>(sample.stamp_ns));
    imu.header.frame_id = "imu_link";
    imu.angular_velocity.x = sample.values[0];
    imu.angular_velocity.y = sample.values[1];
    imu.angular_velocity.z = sample.values[2];
    imu.linear_acceleration.x = sample.values[3];
    imu.linear_acceleration.y = sample.values[4];
    imu.linear_acceleration.z = sample.values[5];
    if (layout.without_angular_rate) {
      imu.angular_velocity = geometry_msgs::Vector3();
      imu.angular_velocity_covariance[0] = -1.0;
    }
    if (layout.without_specific_force) {
      imu.linear_acceleration = geometry_msgs::Vector3();
      imu.linear_acceleration_covariance[0] = -1.0;
    }
    // The view orders by record time: keep it strictly increasing (the arrival order), so
    // unordered or duplicate header stamps reach the reader as they were recorded.
    record_ns = std::max(record_ns + 1, sample.stamp_ns);
    ros::Time record_time;
    record_time.fromNSec(static_cast<std::uint64_t>(record_ns));
    for (const std::string& topic : layout.imu_topics) bag.write(topic, record_time, imu);
    if (layout.with_temperature && i % 10 == 0) {
      sensor_msgs::Temperature temperature;
      temperature.header.stamp = imu.header.stamp;
      temperature.temperature = 25.0;
      bag.write("/imu/temperature", record_time, temperature);
    }
  }
}

YAML::Node read_allan_summary(const std::string& report_directory) {
  return YAML::LoadFile(report_directory + "/allan_summary.yaml");
}

bool CsvTable::has_column(const std::string& name) const {
  return std::find(header.begin(), header.end(), name) != header.end();
}

std::vector<double> CsvTable::column(const std::string& name) const {
  const auto found = std::find(header.begin(), header.end(), name);
  if (found == header.end()) throw std::out_of_range("CSV has no column '" + name + "'");
  const std::size_t index = static_cast<std::size_t>(found - header.begin());
  std::vector<double> values;
  for (const auto& row : rows) values.push_back(index < row.size() ? row[index] : std::nan(""));
  return values;
}

CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  CsvTable table;
  std::string line;
  std::getline(in, line);
  std::istringstream names(line);
  for (std::string name; std::getline(names, name, ',');) table.header.push_back(name);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream cells(line);
    std::vector<double> row;
    for (std::string cell; std::getline(cells, cell, ',');) {
      char* end = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0') throw std::runtime_error(path + ": '" + cell + "' is not a number");
      row.push_back(value);
    }
    table.rows.push_back(row);
  }
  return table;
}

}  // namespace test_support
}  // namespace imu_lab
