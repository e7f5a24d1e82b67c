// export_csv: a bag's sensor_msgs/Imu topic (with the temperature readings at the same stamps)
// -> CSV with a header naming each column's unit, SI by default; --gyro-unit deg_s and
// --accel-unit g for people who think in those; --time-offset-s takes off the offset import_csv
// added. Written atomically. import_csv reads it back.
#include <CLI/CLI.hpp>

#include <cstdio>

#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/ros_io/bag/imu_csv_bag.h"
#include "imu_lab/ros_io/bag/recording_arguments.h"

int main(int argc, char** argv) {
  CLI::App app{"Export a bag's IMU topic to CSV (header with units; SI unless asked otherwise)."};
  constexpr const char* kTool = "export_csv";
  constexpr const char* kCommandLine = "command line";
  imu_lab::ros_io::RecordingArguments recording;
  std::string out_path, delimiter = ",", gyro_unit = "rad_s", accel_unit = "m_s2", temperature_topic;
  std::string time_offset_s = "0";
  bool no_temperature = false;
  imu_lab::ros_io::CsvExportRequest request;
  imu_lab::ros_io::add_recording_arguments(app, recording, "bag to read", false);
  app.add_option("-o,--out", out_path, "CSV file to write")->required();
  app.add_option("--topic", request.imu_topic, "sensor_msgs/Imu topic (default: the bag's only one)");
  auto* temperature_option = app.add_option(
      "--temperature-topic", temperature_topic,
      "sensor_msgs/Temperature topic for a temperature_c column (default: /imu/temperature if the bag has it)");
  app.add_flag("--no-temperature", no_temperature, "no temperature column")->excludes(temperature_option);
  app.add_option("--gyro-unit", gyro_unit, "rad_s or deg_s")->capture_default_str();
  app.add_option("--accel-unit", accel_unit, "m_s2 or g (9.80665 m/s^2)")->capture_default_str();
  app.add_option("--delimiter", delimiter, "',' ';' or tab")->capture_default_str();
  app.add_option("--time-offset-s", time_offset_s,
                 "taken off every stamp: the offset import_csv added (its --time-offset-s, or the 1000000000 s it "
                 "adds to a time column that starts near 0); the same number gives the file's times back")
      ->capture_default_str();
  if (const auto status = imu_lab::parse_tool_options("export_csv", app, argc, argv)) return *status;

  imu_lab::ToolInput input = recording.tool_input(request.imu_topic);
  return imu_lab::run_tool_main(kTool, input, [&] {
    using namespace imu_lab::io;
    request.format.delimiter = parse_delimiter(delimiter, kCommandLine, "--delimiter");
    request.format.gyro_unit = parse_angular_rate_unit(gyro_unit, kCommandLine, "--gyro-unit");
    request.format.accel_unit = parse_specific_force_unit(accel_unit, kCommandLine, "--accel-unit");
    request.format.time_offset_ns = parse_time_offset_ns(time_offset_s, kCommandLine, "--time-offset-s");
    if (!temperature_topic.empty()) {
      request.temperature_topic = temperature_topic;
      request.temperature_required = true;
    }
    if (no_temperature) request.temperature_topic.clear();
    const auto report = imu_lab::ros_io::export_bag_to_csv(recording.recording(), request, out_path);
    std::printf("%s: wrote %s: %zu rows of %s (gyro %s, accel %s)", kTool, out_path.c_str(), report.rows,
                report.imu_topic.c_str(), gyro_unit.c_str(), accel_unit.c_str());
    if (!report.temperature_topic.empty()) {
      std::printf(", temperature_c from %s in %zu rows", report.temperature_topic.c_str(),
                  report.rows_with_temperature);
      if (report.unmatched_temperatures > 0) {
        std::printf(" (%zu readings at stamps without an IMU sample left out)", report.unmatched_temperatures);
      }
    }
    std::printf("\n");
    return 0;
  });
}
