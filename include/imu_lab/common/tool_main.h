// Every command-line tool's body runs through here, so all tools refuse the same readable way:
// one line "<tool>: ..." on stderr and exit status 2 for a bad configuration, 1 for anything else
// (bad data, unreadable files). No exception ever escapes as an abort.
#pragma once

#include <functional>
#include <string>

namespace imu_lab {

// What a tool reads. Every refusal of bad data names it: an error raised deep in a fit or a
// statistic ("no static intervals found") reaches the user as "bag x.bag, topic /imu/raw: no
// static intervals found". The body may fill in the topic once it has chosen one.
struct ToolInput {
  std::string kind = "bag";  // "bag", "CSV file", ...
  std::string path;
  std::string topic;  // empty: not chosen yet
  // "bag x.bag, topic /imu/raw"
  std::string describe() const;
  // `message` with describe() in front unless it already names the path.
  std::string name_in(const std::string& message) const;
};

// body returns the tool's exit status when it finishes on its own.
int run_tool_main(const char* tool_name, const std::function<int()>& body);
int run_tool_main(const char* tool_name, const ToolInput& input, const std::function<int()>& body);

}  // namespace imu_lab
