// Command-line parsing shared by every tool, so all of them refuse a bad option the same way as
// any other bad configuration (tool_main.h): one line "<tool>: bad configuration: <option>: ..."
// on stderr and exit status 2, never CLI11's own codes (104-114). Every numeric option is checked
// here for finiteness (NaN, Inf and overflowing text such as 1e400 are refused) and, for unsigned
// options, for a sign CLI11 would wrap around; ranges are each option's validator below.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>

namespace imu_lab {

// Parses argv into app's variables. Returns the exit status when the tool must stop now: 0 after
// --help (printed), 2 on a bad option (refusal printed); empty when the tool should run.
std::optional<int> parse_tool_options(const char* tool_name, CLI::App& app, int argc, char** argv);

namespace option_range {

// Validators for add_option(...)->check(...): a finite number with the bound(s) named in the
// refusal, e.g. "--rate-hz: must be > 0, got -5".
CLI::Validator positive();                               // > 0
CLI::Validator non_negative();                           // >= 0
CLI::Validator at_least(double minimum);                 // >= minimum
CLI::Validator between(double minimum, double maximum);  // [minimum, maximum]
CLI::Validator latitude_deg();                           // [-90, 90]
CLI::Validator longitude_deg();                          // [-180, 360]
CLI::Validator height_m();                               // [-11000, 100000]: the deepest trench to near space

}  // namespace option_range
}  // namespace imu_lab
