// Helpers for ROS-layer tests: scratch folders, running the package's tools as subprocesses.
#pragma once

#include <string>
#include <vector>

namespace imu_lab {
namespace test_support {

// A fresh directory under /tmp, removed by nobody (tests are small; CI machines are fresh).
std::string scratch_directory();

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs one of the package's executables (from the devel space) with arguments, shell-quoted.
CommandResult run_tool(const std::string& tool, const std::string& arguments);
// The path of one of the package's executables.
std::string tool_path(const std::string& tool);
// Runs a shell command line (/bin/sh -c; e.g. one of the package's scripts), stderr with stdout.
CommandResult run_command(const std::string& command);

std::string read_file(const std::string& path);
// Writes the first `fraction` of source's bytes to destination (a recording cut short by a crash);
// returns destination.
std::string write_truncated_copy(const std::string& source, const std::string& destination, double fraction);
bool file_exists(const std::string& path);
// Whether a tool's output holds the expected words.
bool contains(const std::string& text, const std::string& part);
// Sorted names of the entries of a directory (without . and ..).
std::vector<std::string> list_directory(const std::string& path);
// The thesis's 12 orientations (config/scenarios/multiposition_12_thesis.yaml) with 6 s dwells and
// fast moves, written into `directory`: a calibration bag of about 110 s. Returns its path.
std::string write_quick_twelve_position_schedule(const std::string& directory);

}  // namespace test_support
}  // namespace imu_lab
