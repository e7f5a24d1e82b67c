// The ROS side of CSV import and export: a logger's CSV (io/csv_imu_import.h) into a bag of
// sensor_msgs/Imu (+ sensor_msgs/Temperature), and a bag's IMU topic back into CSV
// (io/csv_imu_export.h). Both outputs appear only when complete (AtomicBag, atomic file).
#pragma once

#include <cstddef>
#include <string>

#include "imu_lab/io/csv_imu_export.h"
#include "imu_lab/io/csv_imu_import.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"

namespace imu_lab {
namespace ros_io {

struct CsvBagTopics {
  std::string imu = "/imu/raw";
  std::string temperature = "/imu/temperature";
  std::string frame_id = "imu_link";
};

struct CsvImportReport {
  io::CsvImportSummary summary;
  std::size_t temperature_messages = 0;
};

// Parses csv_path and writes bag_path. With BadRowPolicy::kRefuse any bad row -> InputError
// listing them (line numbers, reasons, count) and no bag; with kSkip the bag holds the good rows
// and the report lists the bad ones for the caller to print. A mapping that does not fit the
// file -> ConfigError.
CsvImportReport import_csv_to_bag(const std::string& csv_path, const io::CsvImportOptions& options,
                                  const CsvBagTopics& topics, const std::string& bag_path);

struct CsvExportRequest {
  std::string imu_topic;                               // empty: the bag's only sensor_msgs/Imu topic
  std::string temperature_topic = "/imu/temperature";  // used if the bag has it; empty: none
  bool temperature_required = false;                   // the topic was asked for: missing -> InputError
  io::CsvExportOptions format;
};

struct CsvExportReport {
  std::string imu_topic;
  std::string temperature_topic;  // empty: no temperature column
  std::size_t rows = 0;
  std::size_t rows_with_temperature = 0;
  std::size_t unmatched_temperatures = 0;  // readings at stamps without an IMU sample (not exported)
};

// Reads the IMU topic (and the temperature readings at the same header stamps) into csv_path.
CsvExportReport export_bag_to_csv(const BagRecording& recording, const CsvExportRequest& request,
                                  const std::string& csv_path);

}  // namespace ros_io
}  // namespace imu_lab
