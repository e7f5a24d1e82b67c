// Strict YAML field readers for profiles, scenarios and models: every refusal is a ConfigError
// naming the dotted key path.
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <initializer_list>
#include <string>
#include <vector>

namespace imu_lab {

class YamlFields {
 public:
  YamlFields(const YAML::Node& node, std::string path, std::string source);

  // Refuses any key not listed (catches typos and unknown noise names).
  void allow_only(std::initializer_list<const char*> keys) const;
  bool has(const std::string& key) const;
  YamlFields child(const std::string& key) const;                  // required mapping
  YAML::Node raw(const std::string& key) const;                    // required, any shape
  std::vector<YamlFields> mappings(const std::string& key) const;  // required non-empty list

  double number(const std::string& key) const;
  double number_or(const std::string& key, double fallback) const;
  double non_negative(const std::string& key) const;
  double positive(const std::string& key) const;
  std::string text(const std::string& key) const;
  // A scalar (same on all axes) or a sequence of three numbers.
  Eigen::Vector3d per_axis(const std::string& key, bool non_negative_only) const;
  Eigen::Vector3d per_axis_or_zero(const std::string& key) const;
  Eigen::Matrix3d matrix3(const std::string& key) const;  // three rows of three numbers
  Eigen::Matrix3d matrix3_or_zero(const std::string& key) const;

  // One scalar element of a sequence; key labels it in messages ("range[0]").
  double number_at(const YAML::Node& value, const std::string& key) const;
  Eigen::Vector3d per_axis_at(const YAML::Node& value, const std::string& key, bool non_negative_only) const;

  std::string key_path(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;
  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  const std::string& source() const { return source_; }

 private:
  YAML::Node node_;
  std::string path_;
  std::string source_;
};

// Loads a file; unreadable or unparsable files are ConfigErrors on key "(file)".
YAML::Node load_yaml_file(const std::string& path);

}  // namespace imu_lab
