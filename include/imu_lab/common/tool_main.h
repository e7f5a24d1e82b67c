// Every command-line tool's body runs through here, so all tools refuse the same readable way:
// one line "<tool>: ..." on stderr and exit status 2 for a bad configuration, 1 for anything else
// (bad data, unreadable files). No exception ever escapes as an abort.
#pragma once

#include <functional>

namespace imu_lab {

// body returns the tool's exit status when it finishes on its own.
int run_tool_main(const char* tool_name, const std::function<int()>& body);

}  // namespace imu_lab
