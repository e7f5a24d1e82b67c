#include "imu_lab/common/yaml_fields.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "imu_lab/common/config_error.h"

namespace imu_lab {

YamlFields::YamlFields(const YAML::Node& node, std::string path, std::string source)
    : node_(node), path_(std::move(path)), source_(std::move(source)) {
  if (!node_.IsMap()) {
    throw ConfigError(source_, path_.empty() ? "(root)" : path_, "expected a mapping of keys");
  }
}

std::string YamlFields::key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

void YamlFields::fail(const std::string& key, const std::string& problem) const {
  throw ConfigError(source_, key_path(key), problem);
}

void YamlFields::allow_only(std::initializer_list<const char*> keys) const {
  for (const auto& entry : node_) {
    // YAML allows a list or a map as a key ("? [a, b]: 1"); no key of ours is one.
    if (!entry.first.IsScalar()) fail("(key)", "a key must be a plain name, not a list or a map");
    const std::string key = entry.first.Scalar();
    if (std::none_of(keys.begin(), keys.end(), [&](const char* k) { return key == k; })) {
      std::string known;
      for (const char* k : keys) known += std::string(known.empty() ? "" : ", ") + k;
      fail(key, "unknown key (expected one of: " + known + ")");
    }
  }
}

bool YamlFields::has(const std::string& key) const { return static_cast<bool>(node_[key]); }

YAML::Node YamlFields::raw(const std::string& key) const {
  const YAML::Node value = node_[key];
  if (!value) fail(key, "missing required key");
  return value;
}

YamlFields YamlFields::child(const std::string& key) const {
  const YAML::Node value = raw(key);
  if (!value.IsMap()) fail(key, "expected a mapping");
  return YamlFields(value, key_path(key), source_);
}

double YamlFields::number_at(const YAML::Node& value, const std::string& key) const {
  if (!value.IsScalar()) fail(key, "expected a number");
  double result = 0.0;
  if (!YAML::convert<double>::decode(value, result) || !std::isfinite(result)) {
    fail(key, "expected a finite number, got '" + value.Scalar() + "'");
  }
  return result;
}

double YamlFields::number(const std::string& key) const { return number_at(raw(key), key); }

double YamlFields::number_or(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

double YamlFields::non_negative(const std::string& key) const {
  const double value = number(key);
  if (value < 0.0) fail(key, "must be non-negative");
  return value;
}

double YamlFields::positive(const std::string& key) const {
  const double value = number(key);
  if (!(value > 0.0)) fail(key, "must be positive");
  return value;
}

std::string YamlFields::text(const std::string& key) const {
  const YAML::Node value = raw(key);
  if (!value.IsScalar()) fail(key, "expected a string");
  return value.Scalar();
}

Eigen::Vector3d YamlFields::per_axis(const std::string& key, bool non_negative_only) const {
  return per_axis_at(raw(key), key, non_negative_only);
}

Eigen::Vector3d YamlFields::per_axis_at(const YAML::Node& value, const std::string& key, bool non_negative_only) const {
  Eigen::Vector3d result;
  if (value.IsScalar()) {
    result.setConstant(number_at(value, key));
  } else if (value.IsSequence() && value.size() == 3) {
    for (int i = 0; i < 3; ++i) result[i] = number_at(value[i], key + "[" + std::to_string(i) + "]");
  } else {
    fail(key, "expected a number or a list of three numbers [x, y, z]");
  }
  if (non_negative_only && result.minCoeff() < 0.0) {
    fail(key, "must be non-negative");
  }
  return result;
}

std::vector<YamlFields> YamlFields::mappings(const std::string& key) const {
  const YAML::Node list = raw(key);
  if (!list.IsSequence() || list.size() == 0) fail(key, "expected a non-empty list of mappings");
  std::vector<YamlFields> result;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string item = key_path(key) + "[" + std::to_string(i) + "]";
    if (!list[i].IsMap()) throw ConfigError(source_, item, "expected a mapping");
    result.emplace_back(list[i], item, source_);
  }
  return result;
}

Eigen::Vector3d YamlFields::per_axis_or_zero(const std::string& key) const {
  return has(key) ? per_axis(key, false) : Eigen::Vector3d::Zero();
}

Eigen::Matrix3d YamlFields::matrix3_or_zero(const std::string& key) const {
  return has(key) ? matrix3(key) : Eigen::Matrix3d::Zero();
}

Eigen::Matrix3d YamlFields::matrix3(const std::string& key) const {
  Eigen::Matrix3d result;
  const YAML::Node value = raw(key);
  if (!value.IsSequence() || value.size() != 3) fail(key, "expected a 3x3 matrix (three rows)");
  for (int r = 0; r < 3; ++r) {
    const std::string row_key = key + "[" + std::to_string(r) + "]";
    if (!value[r].IsSequence() || value[r].size() != 3) fail(row_key, "expected a row of three numbers");
    for (int c = 0; c < 3; ++c) {
      result(r, c) = number_at(value[r][c], row_key + "[" + std::to_string(c) + "]");
    }
  }
  return result;
}

YAML::Node load_yaml_file(const std::string& path) {
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ConfigError(path, "(file)", "cannot open the file");
  } catch (const YAML::Exception& error) {
    throw ConfigError(path, "(file)", std::string("YAML syntax error: ") + error.what());
  }
}

}  // namespace imu_lab
