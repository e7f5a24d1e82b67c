#include "imu_lab/ros_io/bag/allan_report.h"

#include <stdexcept>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/ros_io/node/config_paths.h"

namespace imu_lab {
namespace ros_io {
namespace {

// Every file a report may hold, so that files of an earlier report this one does not produce
// (its plot, its noise model) do not stay beside the new curves.
std::vector<std::string> report_file_names() {
  std::vector<std::string> names;
  for (const allan::Statistic statistic : allan::kStreamingStatistics) {
    names.push_back(std::string(allan::statistic_name(statistic)) + ".csv");
  }
  for (const char* name :
       {"allan_summary.yaml", "allan.png", "noise.yaml", "kalibr_imu.yaml", "kalibr_imu_chain.yaml", "warm_up.yaml"})
    names.push_back(name);
  for (const char* channel : pipeline::kAllanChannelNames) names.push_back(pipeline::partial_curves_file_name(channel));
  return names;
}

}  // namespace

std::vector<io::ChannelCurve> channel_curves(const allan::StreamingSnapshot& snapshot, allan::Statistic statistic) {
  std::vector<io::ChannelCurve> curves;
  for (std::size_t c = 0; c < pipeline::kAllanChannelCount && c < snapshot.channels.size(); ++c) {
    curves.push_back({pipeline::kAllanChannelNames[c], pipeline::kAllanChannelUnits[c], snapshot.curve(statistic, c)});
  }
  return curves;
}

AllanReportFiles write_allan_report(const std::string& directory, const pipeline::AllanRunDescription& run,
                                    const allan::StreamingSnapshot& snapshot, bool plot,
                                    const pipeline::AllanIdentifyOptions& identify) {
  // One set: written in full into a staging directory, then moved in together (atomic_file.h).
  OutputSet set;
  const std::string staging = set.stage_directory(directory);
  AllanReportFiles files;
  for (const allan::Statistic statistic : allan::kStreamingStatistics) {
    const std::string name = std::string(allan::statistic_name(statistic)) + ".csv";
    io::write_stability_csv(staging + "/" + name, channel_curves(snapshot, statistic));
    files.written.push_back(name);
  }
  if (run.warm_up) {
    write_file_atomically(staging + "/warm_up.yaml", pipeline::format_warm_up_yaml(run.input, *run.warm_up, snapshot));
    files.written.push_back("warm_up.yaml");
  }
  // After the curves (a failed fit keeps them) and before the plot (it draws the partial curves).
  files.noise = pipeline::write_allan_noise_report(staging, run, snapshot, identify);
  for (const std::string& path : files.noise.written) files.written.push_back(path.substr(staging.size() + 1));
  write_file_atomically(
      staging + "/allan_summary.yaml",
      pipeline::format_allan_summary(run, snapshot) + pipeline::format_identification_summary(identify, files.noise));
  files.written.push_back("allan_summary.yaml");
  for (const std::string& name : report_file_names()) set.remove_at_commit(directory + "/" + name);
  set.commit();
  for (std::string& name : files.written) name = directory + "/" + name;
  // The picture after the numbers are in: drawing it (a Python interpreter and matplotlib) takes
  // about as long as the identification, and a node stopped by roslaunch must not lose its
  // numbers to it. The script writes allan.png atomically itself; the old one went at commit.
  if (plot) {
    const std::string picture = directory + "/allan.png";
    files.plot_problem = run_plot_script("plot_allan.py", {directory, "--statistic", "oadev", "--out", picture});
    if (files.plot_problem.empty())
      files.written.push_back(picture);
    else
      files.plot_problem += ", so no plot";
  }
  return files;
}

}  // namespace ros_io
}  // namespace imu_lab
