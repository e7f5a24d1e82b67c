// Users name shipped configurations by their short name ("tactical_mems", "static") or give
// a path; this resolves both, so every node and tool accepts the same forms. The package's own
// files (config/, scripts/) are found without the workspace being sourced, from where the
// package's library lies: <prefix>/lib/libimu_lab_ros.so has them in <prefix>/share/imu_lab/, in
// an install space (the install rules put them there) and in the devel space alike (the build
// links them there); then ROS_PACKAGE_PATH (a sourced workspace) is asked.
#pragma once

#include <string>
#include <vector>

namespace imu_lab {
namespace ros_io {

// `kind` is the folder under config/ ("sensors", "scenarios", ...). Returns `name_or_path` if it
// is an existing file, else the package's config/<kind>/<name>.yaml if that exists; otherwise
// throws ConfigError listing what was tried (and, when the package itself was not found, what to
// source).
std::string resolve_config(const std::string& kind, const std::string& name_or_path);

// The package's file at `relative_path` ("scripts/plot_allan.py"); ConfigError saying where it
// looked and what to source when it is not found.
std::string package_file(const std::string& relative_path);

// The same search over given package directories (tests).
std::string find_package_file(const std::string& relative_path, const std::vector<std::string>& package_directories);

// The directories package_file searches, best first.
std::vector<std::string> package_directories();

// Runs the package's plotting script scripts/<script> with /usr/bin/python3 (Debian's, which has
// matplotlib) and `arguments`; returns what went wrong, or "" when it succeeded.
std::string run_plot_script(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace ros_io
}  // namespace imu_lab
