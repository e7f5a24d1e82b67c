#include "imu_lab/ros_io/bag/imu_csv_bag.h"

#include <sensor_msgs/Imu.h>
#include <sensor_msgs/Temperature.h>

#include <fstream>
#include <map>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/ros_io/bag/atomic_bag.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/ros_io/msg/vector_message.h"

namespace imu_lab {
namespace ros_io {
namespace {

// A logger's rows carry no covariances and no attitude: covariances all zero ("unknown", as
// sensor_msgs/Imu documents) and orientation marked absent (covariance[0] = -1).
sensor_msgs::Imu to_imu_message(const io::ImuCsvSample& sample, const std_msgs::Header& header) {
  sensor_msgs::Imu message;
  message.header = header;
  message.orientation.w = 1.0;
  message.orientation_covariance.fill(0.0);
  message.orientation_covariance[0] = -1.0;
  message.angular_velocity_covariance.fill(0.0);
  message.linear_acceleration_covariance.fill(0.0);
  set_vector_message(message.angular_velocity, sample.angular_rate_rad_s);
  set_vector_message(message.linear_acceleration, sample.specific_force_m_s2);
  return message;
}

bool bag_has_topic(const BagRecording& recording, const std::string& topic) {
  for (const auto& info : list_topics(recording)) {
    if (info.name == topic) return true;
  }
  return false;
}

}  // namespace

CsvImportReport import_csv_to_bag(const std::string& csv_path, const io::CsvImportOptions& options,
                                  const CsvBagTopics& topics, const std::string& bag_path) {
  std::ifstream in(csv_path);
  if (!in) throw InputError("cannot read " + csv_path);
  CsvImportReport report;
  AtomicBag bag(bag_path);
  std_msgs::Header header;
  header.frame_id = topics.frame_id;
  report.summary = io::parse_imu_csv(in, options, csv_path, [&](const io::ImuCsvSample& sample) {
    header.stamp.fromNSec(static_cast<std::uint64_t>(sample.stamp_ns));
    ++header.seq;
    bag.write(topics.imu, header.stamp, to_imu_message(sample, header));
    if (sample.temperature_c) {
      sensor_msgs::Temperature temperature;
      temperature.header = header;
      temperature.temperature = *sample.temperature_c;
      temperature.variance = 0.0;  // unknown
      bag.write(topics.temperature, header.stamp, temperature);
      ++report.temperature_messages;
    }
  });
  const io::CsvImportSummary& summary = report.summary;
  if (summary.rejected_row_count > 0 && options.bad_rows == io::BadRowPolicy::kRefuse) {
    throw InputError(summary.describe_rejections(csv_path) +
                     "\nnothing written; fix these rows, or pass "
                     "--on-bad-row skip to import the others (a skipped row is a gap in the data)");
  }
  if (summary.accepted_rows == 0)
    throw InputError(summary.describe_rejections(csv_path) + "\nno good row; nothing written");
  bag.commit();
  return report;
}

CsvExportReport export_bag_to_csv(const BagRecording& recording, const CsvExportRequest& request,
                                  const std::string& csv_path) {
  CsvExportReport report;
  report.imu_topic = choose_imu_topic(recording, request.imu_topic);
  if (!request.temperature_topic.empty() &&
      (request.temperature_required || bag_has_topic(recording, request.temperature_topic))) {
    report.temperature_topic = choose_topic(recording, request.temperature_topic, "sensor_msgs/Temperature");
  }
  // Readings by header stamp: a temperature goes on the row of the IMU sample with the same stamp.
  std::map<std::int64_t, double> temperature_by_stamp;
  if (!report.temperature_topic.empty()) {
    for_each_temperature(recording, report.temperature_topic, [&](const TemperatureRecord& record) {
      temperature_by_stamp[record.stamp_ns] = record.temperature_c;
    });
  }
  io::CsvExportOptions format = request.format;
  format.with_temperature = !report.temperature_topic.empty();
  write_file_atomically(csv_path, [&](std::ostream& out) {
    out << io::imu_csv_header(format) << '\n';
    for_each_imu(recording, report.imu_topic, [&](const ImuRecord& record) {
      io::ImuCsvSample sample;
      sample.stamp_ns = record.stamp_ns;
      sample.angular_rate_rad_s = record.angular_rate_rad_s;
      sample.specific_force_m_s2 = record.specific_force_m_s2;
      const auto reading = temperature_by_stamp.find(record.stamp_ns);
      if (reading != temperature_by_stamp.end()) {
        sample.temperature_c = reading->second;
        temperature_by_stamp.erase(reading);
        ++report.rows_with_temperature;
      }
      io::write_imu_csv_row(out, sample, format);
      ++report.rows;
    });
    if (report.rows == 0)
      throw InputError("bag " + recording.name() + ": topic " + report.imu_topic + " has no messages; nothing written");
  });
  report.unmatched_temperatures = temperature_by_stamp.size();
  return report;
}

}  // namespace ros_io
}  // namespace imu_lab
