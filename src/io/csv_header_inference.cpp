#include "imu_lab/io/csv_header_inference.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <set>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace io {
namespace {

enum class Role { kOther, kTime, kGyro, kAccel, kTemperature };
enum class UnitFamily { kNone, kTime, kRate, kForce, kTemperature };

struct Unit {
  UnitFamily family = UnitFamily::kNone;
  TimeUnit time = TimeUnit::kSecond;
  AngularRateUnit rate = AngularRateUnit::kRadPerSecond;
  SpecificForceUnit force = SpecificForceUnit::kMeterPerSecondSquared;
  std::string text;  // as written in the header
};

struct Column {
  std::string field;  // as in the header
  std::string base;   // lower case, without the unit
  Unit unit;
  Role role = Role::kOther;
  int axis = -1;  // 0..2 for x, y, z
};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// "rad s^-1", "rad/s", "deg_s", "ms", "m s^-2", "g", "degC" -> a unit, if it is one we read.
std::optional<Unit> unit_named(const std::string& written) {
  std::string text = lower(trimmed(written));
  for (char& c : text) {
    if (c == '*' || c == '.' || c == '_') c = ' ';
  }
  Unit unit;
  unit.text = trimmed(written);
  const auto is = [&](std::initializer_list<const char*> names) {
    return std::any_of(names.begin(), names.end(), [&](const char* name) { return text == name; });
  };
  if (is({"s", "sec", "second", "seconds"})) {
    unit.family = UnitFamily::kTime;
    unit.time = TimeUnit::kSecond;
  } else if (is({"ms", "msec"})) {
    unit.family = UnitFamily::kTime;
    unit.time = TimeUnit::kMillisecond;
  } else if (is({"us", "usec", "\xC2\xB5s"})) {
    unit.family = UnitFamily::kTime;
    unit.time = TimeUnit::kMicrosecond;
  } else if (is({"ns", "nsec"})) {
    unit.family = UnitFamily::kTime;
    unit.time = TimeUnit::kNanosecond;
  } else if (is({"rad s^-1", "rad/s", "rad s", "rad s-1", "rads^-1", "rad/sec"})) {
    unit.family = UnitFamily::kRate;
    unit.rate = AngularRateUnit::kRadPerSecond;
  } else if (is({"deg s^-1", "deg/s", "deg s", "deg s-1", "dps", "deg/sec", "\xC2\xB0/s"})) {
    unit.family = UnitFamily::kRate;
    unit.rate = AngularRateUnit::kDegreePerSecond;
  } else if (is({"m s^-2", "m/s^2", "m/s2", "m s2", "m s-2", "m s^2"})) {
    unit.family = UnitFamily::kForce;
    unit.force = SpecificForceUnit::kMeterPerSecondSquared;
  } else if (is({"g"})) {
    unit.family = UnitFamily::kForce;
    unit.force = SpecificForceUnit::kStandardGravity;
  } else if (is({"c", "degc", "deg c",
                 "\xC2\xB0"
                 "c",
                 "celsius"})) {
    unit.family = UnitFamily::kTemperature;
  } else {
    return std::nullopt;
  }
  return unit;
}

// The unit in brackets at the end, or a known suffix after '_' ("gyro_x_rad_s" -> rad_s).
void split_unit(const std::string& field, Column& column) {
  std::string name = trimmed(field);
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const auto start = name.rfind(open);
    if (!name.empty() && name.back() == close && start != std::string::npos) {
      if (const auto unit = unit_named(name.substr(start + 1, name.size() - start - 2))) {
        column.unit = *unit;
        name = trimmed(name.substr(0, start));
      }
      break;
    }
  }
  if (column.unit.family == UnitFamily::kNone) {
    // Longest suffixes first, so "_rad_s" is not read as "_s".
    for (const char* suffix : {"_rad_s", "_deg_s", "_m_s2", "_dps", "_degc", "_ns", "_us", "_ms", "_s", "_g", "_c"}) {
      const std::string ending = suffix;
      const std::string lowered = lower(name);
      if (lowered.size() > ending.size() &&
          lowered.compare(lowered.size() - ending.size(), ending.size(), ending) == 0) {
        if (const auto unit = unit_named(ending.substr(1))) {
          column.unit = *unit;
          name = name.substr(0, name.size() - ending.size());
        }
        break;
      }
    }
  }
  column.base = lower(name);
}

bool one_of(const std::string& text, std::initializer_list<const char*> names) {
  return std::any_of(names.begin(), names.end(), [&](const char* name) { return text == name; });
}

// The role from the name (and the unit's family where the name is ambiguous).
void assign_role(Column& column) {
  const std::string& base = column.base;
  const UnitFamily family = column.unit.family;
  if (one_of(base, {"t", "time", "timestamp", "stamp", "time_stamp", "header_stamp"}) ||
      (family == UnitFamily::kTime &&
       (base.find("time") != std::string::npos || base.find("stamp") != std::string::npos))) {
    column.role = Role::kTime;
    return;
  }
  if (one_of(base, {"temperature", "temp", "t_c", "temperature_c"}) ||
      (family == UnitFamily::kTemperature && base.find("temp") != std::string::npos)) {
    column.role = Role::kTemperature;
    return;
  }
  if (base.empty()) return;
  const char last = base.back();
  if (last != 'x' && last != 'y' && last != 'z') return;
  std::string prefix = base.substr(0, base.size() - 1);
  if (!prefix.empty() && prefix.back() == '_') prefix.pop_back();
  column.axis = last - 'x';
  const bool gyro_name = one_of(
      prefix, {"w", "w_rs_s", "gyro", "gyr", "gyroscope", "omega", "angular_velocity", "angular_rate", "rate", "g"});
  const bool accel_name =
      one_of(prefix, {"a", "a_rs_s", "acc", "accel", "accelerometer", "linear_acceleration", "specific_force", "f"});
  if ((gyro_name && family != UnitFamily::kForce) || (family == UnitFamily::kRate && !accel_name)) {
    column.role = Role::kGyro;
  } else if ((accel_name && family != UnitFamily::kRate) || (family == UnitFamily::kForce && !gyro_name)) {
    column.role = Role::kAccel;
  } else {
    column.axis = -1;
  }
}

// The one column of `role` (and axis), or none when there are none or several.
std::optional<std::size_t> only(const std::vector<Column>& columns, Role role, int axis = -1) {
  std::optional<std::size_t> found;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i].role != role || columns[i].axis != axis) continue;
    if (found) return std::nullopt;
    found = i;
  }
  return found;
}

// "2" -> index 1, a name -> its index; none when it is not in the header.
std::optional<std::size_t> index_of(const std::string& spec, const std::vector<std::string>& header) {
  if (!spec.empty() && std::all_of(spec.begin(), spec.end(), [](unsigned char c) { return std::isdigit(c); })) {
    if (spec.size() > 6) return std::nullopt;
    const std::size_t number = std::stoul(spec);
    return number >= 1 && number <= header.size() ? std::optional<std::size_t>(number - 1) : std::nullopt;
  }
  const auto found = std::find(header.begin(), header.end(), spec);
  return found == header.end() ? std::nullopt : std::optional<std::size_t>(found - header.begin());
}

std::string time_unit_text(TimeUnit unit) {
  switch (unit) {
    case TimeUnit::kSecond: return "s";
    case TimeUnit::kMillisecond: return "ms";
    case TimeUnit::kMicrosecond: return "us";
    case TimeUnit::kNanosecond: return "ns";
  }
  return "s";
}

}  // namespace

HeaderInference infer_from_header(const std::vector<std::string>& header, const CsvImportOptions& options,
                                  const std::string& source) {
  HeaderInference out{options, ""};
  CsvImportOptions& inferred = out.options;
  std::vector<Column> columns(header.size());
  for (std::size_t i = 0; i < header.size(); ++i) {
    columns[i].field = header[i];
    split_unit(header[i], columns[i]);
    assign_role(columns[i]);
  }
  std::vector<std::string> notes;

  // Columns by name: only when none was given and the header names all seven unambiguously.
  const auto time = only(columns, Role::kTime);
  std::array<std::optional<std::size_t>, 3> gyro, accel;
  bool all_axes = true;
  for (int axis = 0; axis < 3; ++axis) {
    gyro[axis] = only(columns, Role::kGyro, axis);
    accel[axis] = only(columns, Role::kAccel, axis);
    all_axes = all_axes && gyro[axis] && accel[axis];
  }
  if (!options.given.columns && time && all_axes) {
    inferred.time_column = header[*time];
    for (int axis = 0; axis < 3; ++axis) {
      inferred.gyro_columns[axis] = header[*gyro[axis]];
      inferred.accel_columns[axis] = header[*accel[axis]];
    }
    notes.push_back("columns by name: time '" + header[*time] + "', gyro '" + header[*gyro[0]] + "'.., accel '" +
                    header[*accel[0]] + "'..");
  }
  if (!options.given.columns && !options.given.temperature_column && inferred.temperature_column.empty()) {
    // Only a column that says it is a temperature in degC by its unit, as export_csv writes it, and
    // only when the user mapped no column (a mapping given is the whole mapping).
    const auto temperature = only(columns, Role::kTemperature);
    if (temperature && columns[*temperature].unit.family == UnitFamily::kTemperature) {
      inferred.temperature_column = header[*temperature];
      notes.push_back("temperature '" + header[*temperature] + "'");
    }
  }

  // Units of the mapped columns, where the header names them.
  const auto unit_of = [&](const std::string& spec, UnitFamily family) -> std::optional<Unit> {
    const auto index = index_of(spec, header);
    if (!index || columns[*index].unit.family != family) return std::nullopt;
    return columns[*index].unit;
  };
  const auto triad_unit = [&](const std::array<std::string, 3>& specs, UnitFamily family) -> std::optional<Unit> {
    std::optional<Unit> first = unit_of(specs[0], family);
    for (int axis = 1; axis < 3 && first; ++axis) {
      const auto other = unit_of(specs[axis], family);
      if (!other || other->rate != first->rate || other->force != first->force) return std::nullopt;
    }
    return first;
  };
  std::vector<std::string> units;
  // The header's unit, unless the user gave one; one the header contradicts is refused.
  const auto take = [&](const std::optional<Unit>& unit, bool given, bool agrees, const std::string& role,
                        const std::string& given_name, const std::string& header_name, const std::string& columns) {
    if (!unit) return false;
    if (given && !agrees) {
      throw ConfigError(source, role + " unit",
                        "'" + given_name + "' given, but the header names the " + columns + " in " + unit->text);
    }
    units.push_back(role + " " + header_name);
    return true;
  };
  const auto time_unit = unit_of(inferred.time_column, UnitFamily::kTime);
  if (take(time_unit, options.given.time_unit, time_unit && time_unit->time == options.time_unit, "time",
           time_unit_text(options.time_unit), time_unit ? time_unit_text(time_unit->time) : "",
           "time column '" + inferred.time_column + "'")) {
    inferred.time_unit = time_unit->time;
  }
  const auto gyro_unit = triad_unit(inferred.gyro_columns, UnitFamily::kRate);
  if (take(gyro_unit, options.given.gyro_unit, gyro_unit && gyro_unit->rate == options.gyro_unit, "gyro",
           unit_name(options.gyro_unit), gyro_unit ? unit_name(gyro_unit->rate) : "", "gyro columns")) {
    inferred.gyro_unit = gyro_unit->rate;
  }
  const auto accel_unit = triad_unit(inferred.accel_columns, UnitFamily::kForce);
  if (take(accel_unit, options.given.accel_unit, accel_unit && accel_unit->force == options.accel_unit, "accel",
           unit_name(options.accel_unit), accel_unit ? unit_name(accel_unit->force) : "", "accelerometer columns")) {
    inferred.accel_unit = accel_unit->force;
  }
  if (!units.empty()) {
    std::string text = "units from the header: ";
    for (std::size_t i = 0; i < units.size(); ++i) text += (i == 0 ? "" : ", ") + units[i];
    notes.push_back(text);
  }
  for (std::size_t i = 0; i < notes.size(); ++i) out.description += (i == 0 ? "" : "; ") + notes[i];
  const bool euroc = gyro[0] && columns[*gyro[0]].base == "w_rs_s_x";
  if (euroc && !out.description.empty()) out.description = "EuRoC/ASL format: " + out.description;
  return out;
}

}  // namespace io
}  // namespace imu_lab
