// Users name shipped configurations by their short name ("tactical_mems", "static") or give
// a path; this resolves both, so every node and tool accepts the same forms.
#pragma once

#include <string>

namespace imu_lab {
namespace ros_io {

// `kind` is the folder under config/ ("sensors", "scenarios", ...). Returns `name_or_path` if it
// is an existing file, else <package>/config/<kind>/<name>.yaml if that exists; otherwise throws
// ConfigError listing what was tried.
std::string resolve_config(const std::string& kind, const std::string& name_or_path);

}  // namespace ros_io
}  // namespace imu_lab
