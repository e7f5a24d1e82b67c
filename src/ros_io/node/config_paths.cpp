#include "imu_lab/ros_io/node/config_paths.h"

#include <dlfcn.h>
#include <ros/package.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>

#include "imu_lab/common/config_error.h"

extern char** environ;

namespace imu_lab {
namespace ros_io {
namespace {

const char* const kPython = "/usr/bin/python3";

bool is_file(const std::string& path) {
  struct stat status {};
  return ::stat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode);
}

bool is_directory(const std::string& path) {
  struct stat status {};
  return ::stat(path.c_str(), &status) == 0 && S_ISDIR(status.st_mode);
}

std::string parent_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos || slash == 0 ? std::string("/") : path.substr(0, slash);
}

std::string real_path(const std::string& path) {
  char resolved[PATH_MAX];
  return ::realpath(path.c_str(), resolved) != nullptr ? std::string(resolved) : std::string();
}

// <prefix>/lib/libimu_lab_ros.so -> <prefix>/share/imu_lab (nodes, tools and nodelets alike).
std::string share_beside_library() {
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&package_directories), &info) == 0 || info.dli_fname == nullptr) return "";
  const std::string library = real_path(info.dli_fname);
  if (library.empty()) return "";
  return parent_of(parent_of(library)) + "/share/imu_lab";
}

// <prefix>/lib/imu_lab/<executable> -> <prefix>/share/imu_lab.
std::string share_beside_executable() {
  const std::string executable = real_path("/proc/self/exe");
  if (executable.empty()) return "";
  return parent_of(parent_of(parent_of(executable))) + "/share/imu_lab";
}

std::string what_to_source() {
  return "source the workspace's setup.bash (devel/setup.bash after a build, install/setup.bash after "
         "catkin_make install), or give a path";
}

}  // namespace

std::vector<std::string> package_directories() {
  std::vector<std::string> directories;
  for (const std::string& directory : {share_beside_library(), share_beside_executable()}) {
    if (!directory.empty()) directories.push_back(directory);
  }
  // rospack prints an error of its own when the package is not on ROS_PACKAGE_PATH.
  if (std::getenv("ROS_PACKAGE_PATH") != nullptr) {
    const std::string sourced = ros::package::getPath("imu_lab");
    if (!sourced.empty()) directories.push_back(sourced);
  }
  return directories;
}

std::string find_package_file(const std::string& relative_path, const std::vector<std::string>& package_directories) {
  std::string looked;
  for (const std::string& directory : package_directories) {
    const std::string candidate = directory + "/" + relative_path;
    if (is_file(candidate)) return candidate;
    looked += (looked.empty() ? "" : ", ") + candidate;
  }
  throw ConfigError("imu_lab", relative_path,
                    "the package's file was not found (looked at " + (looked.empty() ? "nothing" : looked) + "); " +
                        what_to_source());
}

std::string package_file(const std::string& relative_path) {
  return find_package_file(relative_path, package_directories());
}

std::string resolve_config(const std::string& kind, const std::string& name_or_path) {
  if (is_file(name_or_path)) return name_or_path;
  const std::string relative = "config/" + kind + "/" + name_or_path + ".yaml";
  const std::vector<std::string> directories = package_directories();
  for (const std::string& directory : directories) {
    if (is_file(directory + "/" + relative)) return directory + "/" + relative;
  }
  for (const std::string& directory : directories) {
    if (is_directory(directory + "/config/" + kind)) {
      throw ConfigError(name_or_path, kind,
                        "no such file, and no shipped configuration " + directory + "/" + relative +
                            " (give a path, or one of the names in config/" + kind + "/)");
    }
  }
  throw ConfigError(
      name_or_path, kind,
      "no such file, and the package's config/" + kind + "/ was not found to look for the name; " + what_to_source());
}

std::string run_plot_script(const std::string& script, const std::vector<std::string>& arguments) {
  std::string script_path;
  try {
    script_path = package_file("scripts/" + script);
  } catch (const ConfigError& error) {
    return error.what();
  }
  std::vector<std::string> command = {kPython, script_path};
  command.insert(command.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& argument : command) argv.push_back(argument.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  if (::posix_spawn(&child, kPython, nullptr, nullptr, argv.data(), environ) != 0) {
    return std::string("cannot run ") + kPython + " " + script_path;
  }
  int status = 0;
  if (::waitpid(child, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return script_path + " failed (see its message above; python3-matplotlib installed?)";
  }
  return "";
}

}  // namespace ros_io
}  // namespace imu_lab
