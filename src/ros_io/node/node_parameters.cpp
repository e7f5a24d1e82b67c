#include "imu_lab/ros_io/node/node_parameters.h"

#include <XmlRpcValue.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "imu_lab/common/format_number.h"

namespace imu_lab {
namespace ros_io {
namespace {

using XmlRpc::XmlRpcValue;

// Enough of a given value to recognise it in the message, however long it is.
constexpr std::size_t kShownLength = 60;

std::string shortened(const std::string& text) {
  return text.size() > kShownLength ? text.substr(0, kShownLength) + "..." : text;
}

// The value as YAML would show it: 'fast', 1.5, true, ['oadev', 3], {...}.
std::string value_text(XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpcValue::TypeBoolean: return static_cast<bool&>(value) ? "true" : "false";
    case XmlRpcValue::TypeInt: return std::to_string(static_cast<int&>(value));
    case XmlRpcValue::TypeDouble: return format_number(static_cast<double&>(value), 6);
    case XmlRpcValue::TypeString: return "'" + shortened(static_cast<std::string&>(value)) + "'";
    case XmlRpcValue::TypeArray: {
      std::string text = "[";
      for (int k = 0; k < value.size() && text.size() <= kShownLength; ++k)
        text += (k > 0 ? ", " : "") + value_text(value[k]);
      return shortened(text) + "]";
    }
    default: return "{...}";
  }
}

std::string describe(XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpcValue::TypeBoolean: return "the bool " + value_text(value);
    case XmlRpcValue::TypeInt: return "the int " + value_text(value);
    case XmlRpcValue::TypeDouble: return "the double " + value_text(value);
    case XmlRpcValue::TypeString: return "the string " + value_text(value);
    case XmlRpcValue::TypeArray: return "the list " + value_text(value);
    case XmlRpcValue::TypeStruct: return "a dictionary";
    default: return "a value of XmlRpc type " + std::to_string(static_cast<int>(value.getType()));
  }
}

// Each supported type: what it is called in a message and how it is taken from a parameter of the
// right XmlRpc type (false: the wrong type).
template <class Value>
struct ParameterType;

template <>
struct ParameterType<double> {
  static constexpr const char* name = "a number (double or int)";
  static bool take(XmlRpcValue& value, double& out) {
    if (value.getType() == XmlRpcValue::TypeDouble) return out = static_cast<double&>(value), true;
    if (value.getType() == XmlRpcValue::TypeInt) return out = static_cast<int&>(value), true;
    return false;
  }
};

// A type taken only from the one XmlRpc type that holds it.
template <class Value, XmlRpcValue::Type kType>
struct ExactParameterType {
  static bool take(XmlRpcValue& value, Value& out) {
    if (value.getType() != kType) return false;
    out = static_cast<Value&>(value);
    return true;
  }
};

template <>
struct ParameterType<int> : ExactParameterType<int, XmlRpcValue::TypeInt> {
  static constexpr const char* name = "an int";
};

template <>
struct ParameterType<bool> : ExactParameterType<bool, XmlRpcValue::TypeBoolean> {
  static constexpr const char* name = "a bool (true or false)";
};

template <>
struct ParameterType<std::string> : ExactParameterType<std::string, XmlRpcValue::TypeString> {
  static constexpr const char* name = "a string";
};

template <>
struct ParameterType<std::vector<std::string>> {
  static constexpr const char* name = "a list of strings";
  static bool take(XmlRpcValue& value, std::vector<std::string>& out) {
    if (value.getType() != XmlRpcValue::TypeArray) return false;
    std::vector<std::string> items;
    for (int k = 0; k < value.size(); ++k) {
      if (value[k].getType() != XmlRpcValue::TypeString) return false;
      items.push_back(static_cast<std::string&>(value[k]));
    }
    out = std::move(items);
    return true;
  }
};

template <>
struct ParameterType<std::vector<double>> {
  static constexpr const char* name = "a list of numbers";
  static bool take(XmlRpcValue& value, std::vector<double>& out) {
    if (value.getType() != XmlRpcValue::TypeArray) return false;
    std::vector<double> items(value.size());
    for (int k = 0; k < value.size(); ++k) {
      if (!ParameterType<double>::take(value[k], items[k])) return false;
    }
    out = std::move(items);
    return true;
  }
};

std::string text_of(double value) { return format_number(value, 6); }

// Nodes read their parameters once, at start-up (nodelets: in one manager, possibly on several
// threads), so the record stays small and the lock uncontended.
std::mutex asked_mutex;
std::vector<std::string> asked_names;

void note_asked(const ros::NodeHandle& node, const std::string& name) {
  const std::string resolved = node.resolveName(name);
  std::lock_guard<std::mutex> lock(asked_mutex);
  if (std::find(asked_names.begin(), asked_names.end(), resolved) == asked_names.end()) asked_names.push_back(resolved);
}

}  // namespace

ConfigError parameter_error(const ros::NodeHandle& node, const std::string& name, const std::string& problem) {
  return ConfigError("ROS parameter", node.resolveName(name), problem);
}

bool has_parameter(const ros::NodeHandle& node, const std::string& name) {
  note_asked(node, name);
  return node.hasParam(name);
}

std::vector<std::string> take_parameters_asked() {
  std::lock_guard<std::mutex> lock(asked_mutex);
  std::vector<std::string> names;
  names.swap(asked_names);
  return names;
}

template <class Value>
Value parameter(const ros::NodeHandle& node, const std::string& name, const Value& fallback) {
  note_asked(node, name);
  XmlRpcValue given;
  if (!node.getParam(name, given)) return fallback;
  Value value{};
  if (!ParameterType<Value>::take(given, value)) {
    throw parameter_error(node, name,
                          std::string("expected ") + ParameterType<Value>::name + ", got " + describe(given));
  }
  return value;
}

template <class Value>
Value positive_parameter(const ros::NodeHandle& node, const std::string& name, const Value& fallback) {
  const Value value = parameter(node, name, fallback);
  if (!(value > 0) || !std::isfinite(static_cast<double>(value))) {
    throw parameter_error(node, name, "must be a positive number, got " + text_of(value));
  }
  return value;
}

template <class Value>
Value non_negative_parameter(const ros::NodeHandle& node, const std::string& name, const Value& fallback) {
  const Value value = parameter(node, name, fallback);
  if (!(value >= 0) || !std::isfinite(static_cast<double>(value))) {
    throw parameter_error(node, name, "must be a number >= 0, got " + text_of(value));
  }
  return value;
}

template double parameter(const ros::NodeHandle&, const std::string&, const double&);
template int parameter(const ros::NodeHandle&, const std::string&, const int&);
template bool parameter(const ros::NodeHandle&, const std::string&, const bool&);
template std::string parameter(const ros::NodeHandle&, const std::string&, const std::string&);
template std::vector<std::string> parameter(const ros::NodeHandle&, const std::string&,
                                            const std::vector<std::string>&);
template std::vector<double> parameter(const ros::NodeHandle&, const std::string&, const std::vector<double>&);
template double positive_parameter(const ros::NodeHandle&, const std::string&, const double&);
template int positive_parameter(const ros::NodeHandle&, const std::string&, const int&);
template double non_negative_parameter(const ros::NodeHandle&, const std::string&, const double&);
template int non_negative_parameter(const ros::NodeHandle&, const std::string&, const int&);

}  // namespace ros_io
}  // namespace imu_lab
