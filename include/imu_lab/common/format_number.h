// Numbers into text with a chosen count of significant digits, locale-free ("%.Ng").
// 17 digits round-trip a double exactly (exchange files); 4 suit a table a person reads.
// format_printf: one number in a printf format of the caller's ("%+.3f"), for terminal summaries.
#pragma once

#include <string>

namespace imu_lab {

constexpr int kRoundTripDigits = 17;

std::string format_number(double value, int significant_digits = kRoundTripDigits);
std::string format_printf(double value, const char* format);

}  // namespace imu_lab
