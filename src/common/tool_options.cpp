#include "imu_lab/common/tool_options.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#include "imu_lab/common/format_number.h"
#include "imu_lab/common/site_limits.h"

namespace imu_lab {
namespace {

// The value as strtod reads it; empty text or trailing characters leave it to CLI11's conversion.
std::optional<double> number_in(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

bool looks_negative(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  return first != std::string::npos && text[first] == '-';
}

// The problem with one value of a numeric option, or "".
std::string numeric_problem(const CLI::Option& option, const std::string& text) {
  const std::string type = option.get_type_name();
  if (type == "FLOAT") {
    const auto value = number_in(text);
    if (value && !std::isfinite(*value)) return "'" + text + "' is not a finite number";
  }
  if (type == "UINT" && looks_negative(text)) return "must not be negative, got " + text;
  return "";
}

std::optional<int> refuse(const char* tool_name, const std::string& problem) {
  std::cerr << tool_name << ": bad configuration: " << problem << " (see " << tool_name << " --help)\n";
  return 2;
}

CLI::Validator range_validator(const std::string& description, bool (*inside)(double, double, double), double low,
                               double high) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const auto value = number_in(text);
        if (!value) return "'" + text + "' is not a number";
        if (!std::isfinite(*value)) return "'" + text + "' is not a finite number";
        if (!inside(*value, low, high)) return "must be " + description + ", got " + text;
        return "";
      },
      description);
}

}  // namespace

std::optional<int> parse_tool_options(const char* tool_name, CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& success) {  // --help
    app.exit(success);
    return 0;
  } catch (const CLI::ParseError& error) {
    return refuse(tool_name, error.what());
  }
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& text : option->results()) {
      const std::string problem = numeric_problem(*option, text);
      if (!problem.empty()) return refuse(tool_name, option->get_name() + ": " + problem);
    }
  }
  return std::nullopt;
}

namespace option_range {

CLI::Validator positive() {
  return range_validator(
      "> 0", [](double value, double, double) { return value > 0.0; }, 0.0, 0.0);
}

CLI::Validator non_negative() {
  return range_validator(
      ">= 0", [](double value, double, double) { return value >= 0.0; }, 0.0, 0.0);
}

CLI::Validator at_least(double minimum) {
  return range_validator(
      ">= " + format_number(minimum, 6), [](double value, double low, double) { return value >= low; }, minimum, 0.0);
}

CLI::Validator between(double minimum, double maximum) {
  return range_validator(
      "in [" + format_number(minimum, 6) + ", " + format_number(maximum, 6) + "]",
      [](double value, double low, double high) { return value >= low && value <= high; }, minimum, maximum);
}

CLI::Validator latitude_deg() { return between(-90.0, 90.0); }
CLI::Validator longitude_deg() { return between(site_limits::kLowestLongitudeDeg, site_limits::kHighestLongitudeDeg); }
CLI::Validator height_m() { return between(site_limits::kLowestHeightM, site_limits::kHighestHeightM); }

}  // namespace option_range
}  // namespace imu_lab
