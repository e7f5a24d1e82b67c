// correct: a recorded bag -> the same bag with its IMU topic thermally compensated and/or
// calibrated, exactly as the live chain (thermal_compensator, then calibration_corrector) would
// publish it, so allan or navigate can run on corrected data offline. Written atomically.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/progress.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/ros_io/bag/bag_correction.h"
#include "imu_lab/ros_io/bag/recording_arguments.h"
#include "imu_lab/thermal/thermal_model_yaml.h"

namespace {

struct CommandLine {
  imu_lab::ros_io::RecordingArguments recording;
  std::string out_path, thermal_model_path, calibration_path;
  imu_lab::ros_io::BagCorrectionOptions options;
};

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "none" : text;
}

void print_summary(const CommandLine& c, const imu_lab::ros_io::BagCorrectionSummary& s) {
  std::string stages;
  if (c.options.thermal_model) stages = "thermal model " + c.thermal_model_path;
  if (c.options.calibration) stages += (stages.empty() ? "" : " then ") + ("calibration " + c.calibration_path);
  std::printf("correct: %zu of %zu IMU messages on %s corrected with %s and written to %s in %s", s.corrected,
              s.imu_messages, s.imu_topic.c_str(), stages.c_str(), s.out_topic.c_str(), c.out_path.c_str());
  if (c.options.thermal_model) {
    std::printf(
        "; %zu temperature readings used; %zu samples outside the thermal model's validity range "
        "(%s) were corrected at its edge (clamped); %zu samples skipped for want of a temperature within "
        "%.3g s of their stamp (as thermal_compensator does)",
        s.temperature_messages, s.clamped, imu_lab::thermal::validity_range_text(*c.options.thermal_model).c_str(),
        s.stale, c.options.max_temperature_age_s);
  }
  std::printf("; %zu other messages copied unchanged (%s)", s.copied_messages, joined(s.copied_topics).c_str());
  if (!s.uncorrected_imu_topics.empty()) {
    std::printf("; note: left uncorrected though they carry the sensor's output: %s",
                joined(s.uncorrected_imu_topics).c_str());
  }
  std::printf(".\n");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Apply a thermal model and/or a calibration to a bag's IMU topic, as the live chain does."};
  CommandLine c;
  auto& o = c.options;
  imu_lab::ros_io::add_recording_arguments(app, c.recording, "bag to correct", false);
  app.add_option("-o,--out", c.out_path, "corrected bag to write (all other topics copied)")->required();
  app.add_option("--thermal-model", c.thermal_model_path, "thermal model YAML written by fit_thermal (applied first)");
  app.add_option("--calibration", c.calibration_path, "calibration YAML written by fit_calibration (applied second)");
  app.add_option("--topic", o.imu_topic, "sensor_msgs/Imu topic (default: the bag's only one)");
  app.add_option("--out-topic", o.out_topic,
                 "topic of the corrected IMU (default: the input topic, replaced; "
                 "another name keeps the raw topic too)");
  app.add_option("--temperature-topic", o.temperature_topic, "thermosensor topic")->capture_default_str();
  app.add_option("--second-temperature-topic", o.second_temperature_topic,
                 "second thermosensor topic (read only if the model uses one)")
      ->capture_default_str();
  app.add_option("--max-temperature-age-s", o.max_temperature_age_s,
                 "farthest a thermosensor reading may be from an IMU stamp [s] (thermal_compensator's parameter)")
      ->capture_default_str()
      ->check(imu_lab::option_range::positive());
  if (const auto status = imu_lab::parse_tool_options("correct", app, argc, argv)) return *status;

  c.recording.on_progress = imu_lab::terminal_progress("correct", "messages");
  imu_lab::ToolInput input = c.recording.tool_input(o.imu_topic);
  return imu_lab::run_tool_main("correct", input, [&] {
    if (c.thermal_model_path.empty() && c.calibration_path.empty()) {
      throw imu_lab::ConfigError("correct", "--thermal-model/--calibration", "give at least one of them");
    }
    if (!c.thermal_model_path.empty()) o.thermal_model = imu_lab::thermal::load_thermal_model(c.thermal_model_path);
    if (!c.calibration_path.empty()) o.calibration = imu_lab::calib::load_calibration(c.calibration_path);
    print_summary(c, imu_lab::ros_io::correct_bag(c.recording.recording(), c.out_path, o));
    return 0;
  });
}
