// spectrum: a static recording in; per channel Welch's PSD with its chi-squared interval and the
// autocorrelation, per triad the axes' correlation matrix at tau0 and after averaging, out as
// DIR/spectrum_psd.csv, DIR/spectrum_autocorrelation.csv, DIR/spectrum.yaml and a plot
// DIR/spectrum.png (one set: all new, or all as they were). Every sample is in them: where allan's
// screens would leave knocks or steps out, a note says so. See
// include/imu_lab/spectrum/spectrum_report.h and doc/spectrum.md.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/identify/noise_report.h"
#include "imu_lab/pipeline/unscreened_disturbances.h"
#include "imu_lab/spectrum/spectrum_report.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/ros_io/bag/recording_arguments.h"
#include "imu_lab/ros_io/bag/strict_imu_reading.h"

int main(int argc, char** argv) {
  CLI::App app{"Power spectral densities, autocorrelations and cross-axis correlation of a static recording."};
  using namespace imu_lab::option_range;
  imu_lab::ros_io::RecordingArguments recording;
  std::string topic, out_directory = "spectrum_report", model_path;
  bool no_plot = false;
  imu_lab::spectrum::SpectrumOptions options;
  imu_lab::ros_io::add_recording_arguments(app, recording, "static bag", true);
  app.add_option("-o,--out", out_directory, "report directory (created)")->capture_default_str();
  app.add_option("--topic", topic, "sensor_msgs/Imu topic (default: the only one in the bag)");
  app.add_option("--segment-length", options.welch.segment_length,
                 "Welch segment in samples (resolution 1 / (length tau0); a power of two is fastest)")
      ->capture_default_str()
      ->check(at_least(8));
  app.add_option("--max-lag-s", options.max_lag_s, "longest autocorrelation lag")
      ->capture_default_str()
      ->check(positive());
  app.add_option("--averaging-factors", options.averaging_factors,
                 "block lengths m (samples) whose means the axis correlation is also computed of")
      ->capture_default_str()
      ->check(at_least(1));
  app.add_option("--confidence", options.confidence, "of every interval (PSD, correlation, white-noise band)")
      ->capture_default_str()
      ->check(between(0.5, 0.999));
  app.add_option("--model", model_path,
                 "noise.yaml of the `allan` tool: each channel's identified model drawn over its PSD (a column "
                 "<channel>_model_psd_... in spectrum_psd.csv, a dashed line in the plot)");
  app.add_flag("--no-plot", no_plot, "do not write spectrum.png");
  if (const auto status = imu_lab::parse_tool_options("spectrum", app, argc, argv)) return *status;

  imu_lab::ToolInput input = recording.tool_input(topic);
  return imu_lab::run_tool_main("spectrum", input, [&] {
    const imu_lab::ros_io::BagRecording bag = recording.recording();
    input.topic = topic = imu_lab::ros_io::choose_imu_topic(bag, topic);
    std::vector<imu_lab::io::ImuRecord> samples;
    imu_lab::pipeline::DisturbanceFinder disturbances;  // what allan would leave out, to say so
    imu_lab::ros_io::for_each_imu_strictly(bag, topic, [&](const imu_lab::io::ImuRecord& record) {
      disturbances.push(record);
      samples.push_back(record);
    });
    imu_lab::spectrum::SpectrumAnalysis analysis = imu_lab::spectrum::analyse_spectra(samples, options);
    if (!model_path.empty()) {
      const auto drawn =
          imu_lab::spectrum::overlay_noise_models(analysis, imu_lab::identify::read_noise_report_file(model_path));
      if (drawn.empty())
        throw imu_lab::InputError(model_path + ": no channel of this recording has a noise model there");
    }

    imu_lab::OutputSet outputs;
    const std::string staging = outputs.stage_directory(out_directory);
    imu_lab::write_file_atomically(staging + "/spectrum_psd.csv", imu_lab::spectrum::psd_csv(analysis));
    imu_lab::write_file_atomically(staging + "/spectrum_autocorrelation.csv",
                                   imu_lab::spectrum::autocorrelation_csv(analysis));
    imu_lab::write_file_atomically(staging + "/spectrum.yaml",
                                   imu_lab::spectrum::correlation_yaml(analysis, bag.name()));
    std::string written = "spectrum_psd.csv, spectrum_autocorrelation.csv, spectrum.yaml";
    // An earlier run's plot is not of this run: without a new one it goes.
    outputs.remove_at_commit(out_directory + "/spectrum.png");
    if (!no_plot) {
      const std::string problem = imu_lab::ros_io::run_plot_script(
          "plot_spectrum.py",
          {staging + "/spectrum_psd.csv", staging + "/spectrum_autocorrelation.csv", staging + "/spectrum.png"});
      if (!problem.empty()) {
        std::fprintf(stderr, "spectrum: warning: plotting failed (%s); the CSV files are the result\n",
                     problem.c_str());
      } else {
        written += ", spectrum.png";
      }
    }
    outputs.commit();
    std::cout << "spectrum: " << bag.name() << ", " << imu_lab::io::describe_time_window(bag.window) << "\n"
              << imu_lab::spectrum::spectrum_summary(analysis)
              << imu_lab::pipeline::unscreened_disturbance_note("spectrum", disturbances.finish(),
                                                                "the spectra, autocorrelations and correlations")
              << "wrote " << written << " in " << out_directory << "\n";
    return 0;
  });
}
