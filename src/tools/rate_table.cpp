// rate_table: a rate-table recording (constant-rate plateaus in both directions at several rates)
// in; per the gyro axis along the table axis the scale-factor error, asymmetry, nonlinearity, bias
// (each with a sigma) and the dead zone's bracket out, as DIR/rate_table.yaml and
// DIR/rate_table_plateaus.csv (one set: both new, or both as they were). The table is
// described by a rate_table scenario (--scenario) or, for a real table, a small YAML file
// (--table). See include/imu_lab/rate_table/scale_factor_test.h and doc/rate_table.md.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/emulator/scenario.h"
#include "imu_lab/rate_table/rate_table_report.h"
#include "imu_lab/rate_table/scale_factor_test.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/ros_io/bag/recording_arguments.h"
#include "imu_lab/ros_io/bag/strict_imu_reading.h"

int main(int argc, char** argv) {
  CLI::App app{"Rate-table scale-factor test of the gyro axis along the table axis."};
  using namespace imu_lab::option_range;
  imu_lab::ros_io::RecordingArguments recording;
  std::string topic, scenario_name, table_path, out_directory = "rate_table_report";
  imu_lab::rate_table::ScaleFactorTestOptions options;
  imu_lab::ros_io::add_recording_arguments(app, recording, "rate-table bag", true);
  app.add_option("-o,--out", out_directory, "report directory (created)")->capture_default_str();
  app.add_option("--topic", topic, "sensor_msgs/Imu topic (default: the only one in the bag)");
  app.add_option("--scenario", scenario_name,
                 "rate_table scenario the bag was emulated from (name in config/scenarios or path)");
  app.add_option("--table", table_path, "YAML describing a real table's run: site, axis, mount, nominal rates");
  app.add_option("--window-s", options.plateaus.window_s, "plateau detection window")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--threshold-sigmas", options.plateaus.threshold_sigmas,
                 "steady: neighbouring window means within this many noise sigmas")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--threshold-rad-s", options.plateaus.threshold_rad_s, "steady threshold (default: from the noise)")
      ->check(non_negative());
  app.add_option("--guard-s", options.plateaus.guard_s, "dropped at each end of a plateau")
      ->capture_default_str()
      ->check(non_negative());
  app.add_option("--min-plateau-s", options.plateaus.min_duration_s, "shortest plateau kept")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--block-s", options.block_s, "block length for the noise of a plateau mean")
      ->capture_default_str()
      ->check(positive());
  if (const auto status = imu_lab::parse_tool_options("rate_table", app, argc, argv)) return *status;

  imu_lab::ToolInput input = recording.tool_input(topic);
  return imu_lab::run_tool_main("rate_table", input, [&] {
    if (scenario_name.empty() == table_path.empty()) {
      throw imu_lab::ConfigError("rate_table", "--scenario/--table", "give exactly one of the two");
    }
    const imu_lab::rate_table::RateTableSetup setup =
        scenario_name.empty() ? imu_lab::rate_table::load_rate_table_setup(table_path)
                              : imu_lab::rate_table::setup_from_scenario(imu_lab::emulator::load_scenario(
                                    imu_lab::ros_io::resolve_config("scenarios", scenario_name)));

    const imu_lab::ros_io::BagRecording bag = recording.recording();
    input.topic = topic = imu_lab::ros_io::choose_imu_topic(bag, topic);
    std::vector<imu_lab::io::ImuRecord> samples;
    imu_lab::ros_io::for_each_imu_strictly(bag, topic,
                                           [&](const imu_lab::io::ImuRecord& record) { samples.push_back(record); });
    const auto result = imu_lab::rate_table::run_scale_factor_test(samples, setup, options);
    const std::string yaml = imu_lab::rate_table::scale_factor_yaml(result, bag.name());
    const std::string csv = imu_lab::rate_table::plateau_csv(result);
    std::filesystem::create_directories(out_directory);
    imu_lab::OutputSet outputs;
    outputs.write(out_directory + "/rate_table.yaml", yaml);
    outputs.write(out_directory + "/rate_table_plateaus.csv", csv);
    outputs.commit();
    std::cout << "rate_table: " << bag.name() << ", " << imu_lab::io::describe_time_window(bag.window) << "\n"
              << imu_lab::rate_table::scale_factor_summary(result) << "wrote " << out_directory << "/rate_table.yaml, "
              << out_directory << "/rate_table_plateaus.csv\n";
    return 0;
  });
}
