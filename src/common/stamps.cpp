#include "imu_lab/common/stamps.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "imu_lab/common/config_error.h"

namespace imu_lab {

std::int64_t stamp_ns_from_seconds(double seconds) {
  const double whole_s = std::floor(seconds);
  return static_cast<std::int64_t>(whole_s) * kNanosecondsPerSecond + std::llround((seconds - whole_s) * 1e9);
}

double seconds_from_stamp_ns(std::int64_t stamp_ns) {
  // Both parts carry the stamp's sign, so a negative stamp reads as its positive mirror does.
  const std::int64_t whole_s = stamp_ns / kNanosecondsPerSecond;
  const std::int64_t fraction_ns = stamp_ns % kNanosecondsPerSecond;
  return static_cast<double>(whole_s) + 1e-9 * static_cast<double>(fraction_ns);
}

std::string format_stamp_s(std::int64_t stamp_ns) {
  const bool negative = stamp_ns < 0;
  // Unsigned so that the most negative stamp has a magnitude too.
  const std::uint64_t magnitude = negative ? 0 - static_cast<std::uint64_t>(stamp_ns) : stamp_ns;
  char text[40];
  std::snprintf(text, sizeof text, "%s%llu.%09llu", negative ? "-" : "",
                static_cast<unsigned long long>(magnitude / kNanosecondsPerSecond),
                static_cast<unsigned long long>(magnitude % kNanosecondsPerSecond));
  return text;
}

std::int64_t parse_stamp_s(const std::string& text) {
  const bool negative = !text.empty() && text[0] == '-';
  const std::string body = negative ? text.substr(1) : text;
  const auto dot = body.find('.');
  const std::string seconds = body.substr(0, dot);
  std::string fraction = dot == std::string::npos ? "" : body.substr(dot + 1);
  const bool digits = !seconds.empty() && seconds.size() <= 18 &&
                      seconds.find_first_not_of("0123456789") == std::string::npos && fraction.size() <= 9 &&
                      fraction.find_first_not_of("0123456789") == std::string::npos;
  if (!digits) throw InputError("'" + text + "' is not a stamp in seconds.nanoseconds");
  const std::int64_t whole_s = std::stoll(seconds);
  if (whole_s >= std::numeric_limits<std::int64_t>::max() / kNanosecondsPerSecond)
    throw InputError("'" + text + "' is beyond the stamps int64 nanoseconds hold");
  fraction.append(9 - fraction.size(), '0');
  const std::int64_t magnitude = whole_s * kNanosecondsPerSecond + std::stoll(fraction);
  return negative ? -magnitude : magnitude;
}

}  // namespace imu_lab
