#include "imu_lab/io/csv_import_config.h"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <set>
#include <sstream>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace io {
namespace {

// Refuses keys outside `allowed`, so a misspelt key is reported instead of ignored.
void check_keys(const YAML::Node& node, const std::string& source, const std::string& path,
                const std::set<std::string>& allowed) {
  if (!node.IsMap()) throw ConfigError(source, path.empty() ? "(document)" : path, "must be a mapping");
  for (const auto& entry : node) {
    // YAML allows a list or a map as a key ("? [a, b]: 1"); no key of ours is one.
    if (!entry.first.IsScalar()) {
      throw ConfigError(source, path.empty() ? "(document)" : path, "a key must be a plain name, not a list or a map");
    }
    const std::string key = entry.first.Scalar();
    if (allowed.count(key) == 0) {
      std::string names;
      for (const auto& name : allowed) names += (names.empty() ? "" : ", ") + name;
      throw ConfigError(source, path.empty() ? key : path + "." + key, "unknown key (known: " + names + ")");
    }
  }
}

std::string scalar(const YAML::Node& node, const std::string& source, const std::string& key) {
  if (!node.IsScalar()) throw ConfigError(source, key, "must be a single value");
  return node.Scalar();
}

bool boolean(const YAML::Node& node, const std::string& source, const std::string& key) {
  try {
    return node.as<bool>();
  } catch (const YAML::Exception&) {
    throw ConfigError(source, key, "must be true or false");
  }
}

void read_triad(const YAML::Node& node, const std::string& source, const std::string& key,
                std::array<std::string, 3>& columns) {
  if (!node.IsSequence() || node.size() != 3) throw ConfigError(source, key, "must list three columns [x, y, z]");
  for (std::size_t i = 0; i < 3; ++i) columns[i] = scalar(node[i], source, key + "[" + std::to_string(i) + "]");
}

}  // namespace

CsvImportOptions parse_csv_import_options(const std::string& yaml_text, const std::string& source,
                                          const CsvImportOptions& defaults) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& error) {
    throw ConfigError(source, "(document)", std::string("not valid YAML: ") + error.what());
  }
  CsvImportOptions options = defaults;
  if (root.IsNull()) return options;
  check_keys(root, source, "", {"delimiter", "header", "decimal_comma", "time", "gyro", "accel", "temperature"});
  if (root["delimiter"])
    options.delimiter = parse_delimiter(scalar(root["delimiter"], source, "delimiter"), source, "delimiter");
  if (root["header"]) options.has_header = boolean(root["header"], source, "header");
  if (root["decimal_comma"]) options.decimal_comma = boolean(root["decimal_comma"], source, "decimal_comma");
  if (const YAML::Node time = root["time"]) {
    check_keys(time, source, "time", {"column", "unit", "offset_s"});
    if (time["column"]) options.time_column = scalar(time["column"], source, "time.column");
    if (time["unit"])
      options.time_unit = parse_time_unit(scalar(time["unit"], source, "time.unit"), source, "time.unit");
    options.given.columns |= bool(time["column"]);
    options.given.time_unit |= bool(time["unit"]);
    options.given.time_offset |= bool(time["offset_s"]);
    if (time["offset_s"]) {
      options.time_offset_ns =
          parse_time_offset_ns(scalar(time["offset_s"], source, "time.offset_s"), source, "time.offset_s");
    }
  }
  if (const YAML::Node gyro = root["gyro"]) {
    check_keys(gyro, source, "gyro", {"columns", "unit"});
    if (gyro["columns"]) read_triad(gyro["columns"], source, "gyro.columns", options.gyro_columns);
    if (gyro["unit"])
      options.gyro_unit = parse_angular_rate_unit(scalar(gyro["unit"], source, "gyro.unit"), source, "gyro.unit");
    options.given.columns |= bool(gyro["columns"]);
    options.given.gyro_unit |= bool(gyro["unit"]);
  }
  if (const YAML::Node accel = root["accel"]) {
    check_keys(accel, source, "accel", {"columns", "unit"});
    if (accel["columns"]) read_triad(accel["columns"], source, "accel.columns", options.accel_columns);
    if (accel["unit"]) {
      options.accel_unit = parse_specific_force_unit(scalar(accel["unit"], source, "accel.unit"), source, "accel.unit");
    }
    options.given.columns |= bool(accel["columns"]);
    options.given.accel_unit |= bool(accel["unit"]);
  }
  if (const YAML::Node temperature = root["temperature"]) {
    check_keys(temperature, source, "temperature", {"column"});
    if (temperature["column"]) options.temperature_column = scalar(temperature["column"], source, "temperature.column");
    options.given.temperature_column |= bool(temperature["column"]);
  }
  return options;
}

CsvImportOptions load_csv_import_options(const std::string& path, const CsvImportOptions& defaults) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path, "(file)", "cannot read the column-mapping file");
  std::stringstream text;
  text << in.rdbuf();
  return parse_csv_import_options(text.str(), path, defaults);
}

}  // namespace io
}  // namespace imu_lab
