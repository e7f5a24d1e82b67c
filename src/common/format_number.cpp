#include "imu_lab/common/format_number.h"

#include <cstdio>

namespace imu_lab {

std::string format_number(double value, int significant_digits) {
  char text[48];
  std::snprintf(text, sizeof(text), "%.*g", significant_digits, value);
  return text;
}

std::string format_printf(double value, const char* format) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace imu_lab
