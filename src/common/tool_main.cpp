#include "imu_lab/common/tool_main.h"

#include <exception>
#include <iostream>

#include "imu_lab/common/config_error.h"

namespace imu_lab {

std::string ToolInput::describe() const { return kind + " " + path + (topic.empty() ? "" : ", topic " + topic); }

std::string ToolInput::name_in(const std::string& message) const {
  if (path.empty() || message.find(path) != std::string::npos) return message;
  return describe() + ": " + message;
}

int run_tool_main(const char* tool_name, const std::function<int()>& body) {
  return run_tool_main(tool_name, ToolInput{}, body);
}

int run_tool_main(const char* tool_name, const ToolInput& input, const std::function<int()>& body) {
  try {
    return body();
  } catch (const ConfigError& error) {
    std::cerr << tool_name << ": bad configuration: " << error.what() << "\n";
    return 2;
  } catch (const OutputError& error) {  // names the file it could not write
    std::cerr << tool_name << ": " << error.what() << "\n";
    return 1;
  } catch (const std::exception& error) {
    std::cerr << tool_name << ": " << input.name_in(error.what()) << "\n";
    return 1;
  }
}

}  // namespace imu_lab
