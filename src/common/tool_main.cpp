#include "imu_lab/common/tool_main.h"

#include <exception>
#include <iostream>

#include "imu_lab/common/config_error.h"

namespace imu_lab {

int run_tool_main(const char* tool_name, const std::function<int()>& body) {
  try {
    return body();
  } catch (const ConfigError& error) {
    std::cerr << tool_name << ": bad configuration: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << tool_name << ": " << error.what() << "\n";
    return 1;
  }
}

}  // namespace imu_lab
