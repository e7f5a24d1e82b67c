#include "imu_lab/ros/config_paths.h"

#include <ros/package.h>
#include <sys/stat.h>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace ros_io {
namespace {

bool is_file(const std::string& path) {
  struct stat status {};
  return ::stat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode);
}

}  // namespace

std::string resolve_config(const std::string& kind, const std::string& name_or_path) {
  if (is_file(name_or_path)) return name_or_path;
  const std::string package = ros::package::getPath("imu_lab");
  const std::string shipped = package + "/config/" + kind + "/" + name_or_path + ".yaml";
  if (!package.empty() && is_file(shipped)) return shipped;
  throw ConfigError(name_or_path, kind,
                    "no such file, and no shipped configuration " + shipped +
                        " (give a path, or one of the names in config/" + kind + "/)");
}

}  // namespace ros_io
}  // namespace imu_lab
