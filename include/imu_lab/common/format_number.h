// Numbers into text with a chosen count of significant digits, locale-free ("%.Ng").
// 17 digits round-trip a double exactly (exchange files); 4 suit a table a person reads.
#pragma once

#include <string>

namespace imu_lab {

constexpr int kRoundTripDigits = 17;

std::string format_number(double value, int significant_digits = kRoundTripDigits);

}  // namespace imu_lab
