#include "imu_lab/ros/allan_report.h"

#include <ros/package.h>
#include <spawn.h>
#include <sys/wait.h>

#include <filesystem>
#include <stdexcept>

#include "imu_lab/common/atomic_file.h"

extern char** environ;

namespace imu_lab {
namespace ros_io {
namespace {

const char* const kPython = "/usr/bin/python3";

// Runs scripts/plot_allan.py on the CSVs in `directory`; returns what went wrong, or "".
std::string plot_oadev(const std::string& directory) {
  const std::string package_path = ros::package::getPath("imu_lab");
  if (package_path.empty()) return "package imu_lab not found (is the workspace sourced?), so no plot";
  const std::string script = package_path + "/scripts/plot_allan.py";
  const std::string out = directory + "/allan.png";
  std::vector<std::string> arguments = {kPython, script, directory, "--statistic", "oadev", "--out", out};
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  if (::posix_spawn(&child, kPython, nullptr, nullptr, argv.data(), environ) != 0) {
    return std::string("cannot run ") + kPython + " " + script;
  }
  int status = 0;
  if (::waitpid(child, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return script + " failed (see its message above; python3-matplotlib installed?)";
  }
  return "";
}

}  // namespace

std::vector<io::ChannelCurve> channel_curves(const allan::StreamingSnapshot& snapshot, allan::Statistic statistic) {
  std::vector<io::ChannelCurve> curves;
  for (std::size_t c = 0; c < kAllanChannelCount && c < snapshot.channels.size(); ++c) {
    curves.push_back({kAllanChannelNames[c], kAllanChannelUnits[c], snapshot.curve(statistic, c)});
  }
  return curves;
}

AllanReportFiles write_allan_report(const std::string& directory, const AllanRunDescription& run,
                                    const allan::StreamingSnapshot& snapshot, bool plot,
                                    const AllanIdentifyOptions& identify) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw std::runtime_error("cannot create the report directory " + directory + ": " + error.message());
  AllanReportFiles files;
  for (const allan::Statistic statistic : allan::kStreamingStatistics) {
    const std::string path = directory + "/" + allan::statistic_name(statistic) + ".csv";
    io::write_stability_csv(path, channel_curves(snapshot, statistic));
    files.written.push_back(path);
  }
  // After the curves (a failed fit keeps them) and before the plot (it draws the partial curves).
  files.noise = write_allan_noise_report(directory, run, snapshot, identify);
  files.written.insert(files.written.end(), files.noise.written.begin(), files.noise.written.end());
  const std::string summary_path = directory + "/allan_summary.yaml";
  write_file_atomically(summary_path,
                        format_allan_summary(run, snapshot) + format_identification_summary(identify, files.noise));
  files.written.push_back(summary_path);
  if (plot) {
    files.plot_problem = plot_oadev(directory);
    if (files.plot_problem.empty()) files.written.push_back(directory + "/allan.png");
  }
  return files;
}

}  // namespace ros_io
}  // namespace imu_lab
