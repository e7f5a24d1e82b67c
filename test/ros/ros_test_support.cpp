#include "ros_test_support.h"

#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <iterator>
#include <stdexcept>

#include "imu_lab/ros_io/node/config_paths.h"

#ifndef IMU_LAB_BIN_DIR
#define IMU_LAB_BIN_DIR "."
#endif

namespace imu_lab {
namespace test_support {

std::string scratch_directory() {
  char pattern[] = "/tmp/imu_lab_test_XXXXXX";
  const char* made = ::mkdtemp(pattern);
  if (made == nullptr) throw std::runtime_error("mkdtemp failed");
  return made;
}

// IMU_LAB_TOOLS_DIR runs the tests against another build's tools (e.g. an older commit's, to see
// which tests fail before a fix); by default the tools of this build.
std::string tool_path(const std::string& tool) {
  const char* other = std::getenv("IMU_LAB_TOOLS_DIR");
  return std::string(other != nullptr && *other != '\0' ? other : IMU_LAB_BIN_DIR) + "/" + tool;
}

CommandResult run_tool(const std::string& tool, const std::string& arguments) {
  return run_command(tool_path(tool) + " " + arguments);
}

CommandResult run_command(const std::string& command_line) {
  const std::string command = "{ " + command_line + " ; } 2>&1";
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run " + command);
  std::array<char, 4096> buffer{};
  std::size_t read = 0;
  while ((read = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), read);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string write_truncated_copy(const std::string& source, const std::string& destination, double fraction) {
  const std::string bytes = read_file(source);
  std::ofstream(destination, std::ios::binary) << bytes.substr(0, static_cast<std::size_t>(bytes.size() * fraction));
  return destination;
}

bool file_exists(const std::string& path) {
  struct stat status {};
  return ::stat(path.c_str(), &status) == 0;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::vector<std::string> list_directory(const std::string& path) {
  std::vector<std::string> names;
  DIR* directory = ::opendir(path.c_str());
  if (directory == nullptr) return names;
  while (const dirent* entry = ::readdir(directory)) {
    const std::string name = entry->d_name;
    if (name != "." && name != "..") names.push_back(name);
  }
  ::closedir(directory);
  std::sort(names.begin(), names.end());
  return names;
}

std::string write_quick_twelve_position_schedule(const std::string& directory) {
  std::ifstream shipped(ros_io::resolve_config("scenarios", "multiposition_12_thesis"));
  std::string text((std::istreambuf_iterator<char>(shipped)), std::istreambuf_iterator<char>());
  for (const char* dwell : {"dwell_s: 102", "dwell_s: 60"}) {
    for (std::size_t at = text.find(dwell); at != std::string::npos; at = text.find(dwell)) {
      text.replace(at, std::string(dwell).size(), "dwell_s: 6");
    }
  }
  text.replace(text.find("move_rate_deg_s: 10"), 19, "move_rate_deg_s: 90");
  text.replace(text.find("move_acceleration_deg_s2: 20"), 28, "move_acceleration_deg_s2: 180");
  text.replace(text.find("duration_s: 982"), 15, "duration_s: 110");
  const std::string path = directory + "/quick_12.yaml";
  std::ofstream(path) << text;
  return path;
}

}  // namespace test_support
}  // namespace imu_lab
