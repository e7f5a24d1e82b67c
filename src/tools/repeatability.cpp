// repeatability: N recordings of one unit (switch-on to switch-on) -> per-run biases with the
// uncertainty of each run's mean, the Allan minimum (in-run stability) and, given the runs' noise
// reports, their identified terms; across runs the run-to-run bias sigma per channel with its
// chi-squared interval; given several fit_calibration results, the scale-factor and misalignment
// repeatability the same way. Writes DIR/repeatability.csv, .yaml, calibration_repeatability.csv
// and repeatability.png (scripts/plot_repeatability.py), each atomically. See
// include/imu_lab/repeatability/repeatability.h and doc/repeatability.md.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "imu_lab/calib/calibration_file.h"
#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/identify/noise_report.h"
#include "imu_lab/repeatability/repeatability.h"
#include "imu_lab/ros_io/node/config_paths.h"
#include "imu_lab/ros_io/bag/imu_bag_reader.h"
#include "imu_lab/ros_io/bag/strict_imu_reading.h"

namespace {

namespace rep = imu_lab::repeatability;

// "a_0.bag,a_1.bag" -> the split files of one run.
std::vector<std::string> split_files(const std::string& run) {
  std::vector<std::string> files;
  for (std::size_t begin = 0;;) {
    const std::size_t comma = run.find(',', begin);
    files.push_back(run.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin));
    if (comma == std::string::npos) return files;
    begin = comma + 1;
  }
}

rep::RunSummary read_run(const std::string& run, const imu_lab::io::TimeWindow& window, const std::string& topic) {
  const imu_lab::ros_io::BagRecording recording(split_files(run), window);
  const std::string chosen = imu_lab::ros_io::choose_imu_topic(recording, topic);
  std::vector<std::array<double, rep::kChannelCount>> samples;
  std::int64_t first_ns = 0, last_ns = 0;
  imu_lab::ros_io::for_each_imu_strictly(recording, chosen, [&](const imu_lab::io::ImuRecord& record) {
    if (samples.empty()) first_ns = record.stamp_ns;
    last_ns = record.stamp_ns;
    samples.push_back({record.angular_rate_rad_s[0], record.angular_rate_rad_s[1], record.angular_rate_rad_s[2],
                       record.specific_force_m_s2[0], record.specific_force_m_s2[1], record.specific_force_m_s2[2]});
  });
  if (samples.size() < 16) {
    throw imu_lab::InputError("run " + recording.name() + ": " + std::to_string(samples.size()) + " samples (" +
                              imu_lab::io::describe_time_window(window) + "); at least 16 are needed");
  }
  // The mean interval: strict reading has refused unordered stamps.
  const double tau0_s = (last_ns - first_ns) * 1e-9 / (samples.size() - 1);
  return rep::summarise_run(recording.name(), samples, tau0_s);
}

std::vector<std::pair<std::string, double>> calibration_parameters(const std::string& path, bool misalignment) {
  const auto calibration = imu_lab::calib::load_calibration(path);
  std::vector<std::pair<std::string, double>> parameters;
  const char* axes = "xyz";
  for (const auto& [triad, name] :
       {std::pair{&calibration.gyro, "gyro"}, std::pair{&calibration.accelerometer, "accel"}}) {
    const Eigen::Vector3d ppm = triad->scale_factor_error_ppm();
    const Eigen::Matrix3d arcsec = triad->misalignment_arcsec();
    for (int i = 0; i < 3; ++i) {
      if (!misalignment) {
        parameters.push_back({std::string(name) + "_scale_factor_" + axes[i], ppm[i]});
        continue;
      }
      for (int j = 0; j < 3; ++j) {
        if (i != j) parameters.push_back({std::string(name) + "_misalignment_" + axes[i] + axes[j], arcsec(i, j)});
      }
    }
  }
  return parameters;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Run-to-run repeatability of one unit from N recordings (and N calibrations)."};
  std::vector<std::string> runs, noise_reports, calibrations;
  std::string out_directory = "repeatability", topic;
  imu_lab::io::TimeWindow window;
  double confidence = 0.95;
  bool no_plot = false;
  app.add_option("runs", runs, "one bag per run (split files of one run joined with commas: a_0.bag,a_1.bag)");
  app.add_option("-o,--out", out_directory, "report directory (created)")->capture_default_str();
  app.add_option("--topic", topic, "sensor_msgs/Imu topic (default: the only one)");
  app.add_option("--start-s", window.start_s, "use each run from this many seconds after its first stamp")
      ->capture_default_str();
  app.add_option("--end-s", window.end_s, "... up to this many seconds after its first stamp");
  app.add_option("--noise-reports", noise_reports, "the runs' noise.yaml (from allan), in the order of the runs");
  app.add_option("--calibrations", calibrations, "several fit_calibration results of the unit");
  app.add_option("--confidence", confidence, "two-sided confidence of the chi-squared intervals")
      ->capture_default_str();
  app.add_flag("--no-plot", no_plot, "do not write repeatability.png");
  if (const auto status = imu_lab::parse_tool_options("repeatability", app, argc, argv)) return *status;

  return imu_lab::run_tool_main("repeatability", [&] {
    if (!(confidence > 0.0 && confidence < 1.0)) {
      throw imu_lab::ConfigError("repeatability", "--confidence", "must be between 0 and 1");
    }
    if (runs.size() == 1 || (runs.empty() && calibrations.size() < 2)) {
      throw imu_lab::ConfigError("repeatability", "runs", "give at least 2 runs (or at least 2 --calibrations)");
    }
    if (!noise_reports.empty() && noise_reports.size() != runs.size()) {
      throw imu_lab::ConfigError("repeatability", "--noise-reports",
                                 "gives " + std::to_string(noise_reports.size()) + " reports for " +
                                     std::to_string(runs.size()) + " runs; give one per run, in order");
    }
    if (calibrations.size() == 1) {
      throw imu_lab::ConfigError("repeatability", "--calibrations", "a spread needs at least 2 calibrations");
    }
    // The tables, the plot and the calibration spreads are one set: all new, or all as they were.
    imu_lab::OutputSet outputs;
    const std::string staging = outputs.stage_directory(out_directory);
    std::vector<std::string> written;  // names in out_directory
    if (!runs.empty()) {
      std::vector<rep::RunSummary> summaries;
      for (std::size_t k = 0; k < runs.size(); ++k) {
        summaries.push_back(read_run(runs[k], window, topic));
        if (!noise_reports.empty()) {
          summaries.back().terms = rep::identified_terms(imu_lab::identify::read_noise_report_file(noise_reports[k]));
        }
        std::fprintf(stderr, "repeatability: run %zu/%zu %s: %zu samples\n", k + 1, runs.size(),
                     summaries.back().name.c_str(), summaries.back().sample_count);
      }
      const auto table = rep::repeatability_table(summaries, confidence);
      const std::string csv = staging + "/repeatability.csv";
      imu_lab::write_file_atomically(csv, rep::repeatability_csv(table));
      imu_lab::write_file_atomically(staging + "/repeatability.yaml", rep::repeatability_yaml(table));
      written = {"repeatability.csv", "repeatability.yaml"};
      std::printf("repeatability: %zu runs, %s; run-to-run bias sigma (n - 1) with its %.0f %% interval:\n",
                  runs.size(), imu_lab::io::describe_time_window(window).c_str(), 100.0 * confidence);
      for (std::size_t c = 0; c < rep::kChannelCount; ++c) {
        const auto& s = table.bias_spread[c];
        std::printf("  %-8s mean %13.6g  sigma %11.4g [%11.4g, %11.4g] %s; rms uncertainty of a run's mean %.3g\n",
                    rep::kChannelNames[c], s.mean, s.standard_deviation, s.lower, s.upper, rep::kChannelUnits[c],
                    table.rms_mean_uncertainty[c]);
      }
      // An earlier run's plot is not of these runs: without a new one it goes.
      outputs.remove_at_commit(out_directory + "/repeatability.png");
      if (!no_plot) {
        const std::string problem =
            imu_lab::ros_io::run_plot_script("plot_repeatability.py", {csv, staging + "/repeatability.png"});
        if (!problem.empty()) {
          std::fprintf(stderr, "repeatability: warning: plotting failed (%s); the CSV is the result\n",
                       problem.c_str());
        } else {
          written.push_back("repeatability.png");
        }
      }
    }
    if (!calibrations.empty()) {
      std::vector<std::vector<std::pair<std::string, double>>> scale_factors, misalignments;
      for (const std::string& path : calibrations) {
        scale_factors.push_back(calibration_parameters(path, false));
        misalignments.push_back(calibration_parameters(path, true));
      }
      imu_lab::write_file_atomically(
          staging + "/calibration_repeatability.csv",
          rep::parameter_spreads_csv(rep::parameter_spreads(scale_factors, "ppm", confidence)) +
              rep::parameter_spreads_csv(rep::parameter_spreads(misalignments, "arcsec", confidence)));
      std::printf("repeatability: %zu calibrations\n", calibrations.size());
      written.push_back("calibration_repeatability.csv");
    }
    outputs.commit();
    for (const std::string& name : written)
      std::printf("repeatability: wrote %s/%s\n", out_directory.c_str(), name.c_str());
    return 0;
  });
}
