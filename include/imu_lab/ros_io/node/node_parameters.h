// Strict reading of a node's ROS parameters, for every node and nodelet. NodeHandle::param falls
// back to the default when a parameter has the wrong type (`_rate_hz:=fast`, `_seed:=1.5`), so a
// node would run unattended with settings nobody asked for. Here: an absent parameter takes the
// default; a present one must have the XmlRpc type of the value (an int will do for a double);
// anything else throws ConfigError naming the fully resolved parameter, the expected type and what
// was given ("ROS parameter: /imu_emulator/rate_hz: expected a number (double or int), got the
// string 'fast'"), which run_node_main turns into ROS_FATAL and exit status 2.
#pragma once

#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace ros_io {

// Value: double, int, bool, std::string, std::vector<std::string> or std::vector<double> (ints will do).
template <class Value>
Value parameter(const ros::NodeHandle& node, const std::string& name, const Value& fallback);

// Numbers with a range: finite and > 0, or finite and >= 0 (Value: double or int).
template <class Value>
Value positive_parameter(const ros::NodeHandle& node, const std::string& name, const Value& fallback);
template <class Value>
Value non_negative_parameter(const ros::NodeHandle& node, const std::string& name, const Value& fallback);

// Whether the parameter is set (for parameters without a default); asked for like the others.
bool has_parameter(const ros::NodeHandle& node, const std::string& name);

// The resolved names of every parameter asked for through this header since the last call, in
// order, each once: how a test holds a node's parameter template (config/nodes/<node>.yaml) to
// exactly the parameters the node reads.
std::vector<std::string> take_parameters_asked();

// The error for a parameter whose value the caller found wrong, e.g. "must be above 1, got 0.5".
ConfigError parameter_error(const ros::NodeHandle& node, const std::string& name, const std::string& problem);

}  // namespace ros_io
}  // namespace imu_lab
