// Stamps are integer nanoseconds (doc/conventions.md): a double of seconds near 1.7e9 s resolves
// only ~0.24 us, so stamps are kept as int64 and turned into seconds only for a difference or for
// text. The conversions from seconds round as ros::Time::fromSec does (whole seconds, then the
// fraction to the nearest nanosecond), so an emulated stamp equals the one its message carries.
#pragma once

#include <cstdint>
#include <string>

namespace imu_lab {

constexpr std::int64_t kNanosecondsPerSecond = 1000000000;

// Seconds (a stamp or a duration) to the nearest nanosecond.
std::int64_t stamp_ns_from_seconds(double seconds);
// A stamp as seconds, as ros::Time::toSec gives it (for messages and printed figures only).
double seconds_from_stamp_ns(std::int64_t stamp_ns);
// later - earlier in seconds, exact to the nanosecond before the one rounding to double.
inline double seconds_between(std::int64_t earlier_ns, std::int64_t later_ns) {
  return static_cast<double>(later_ns - earlier_ns) * 1e-9;
}

// "seconds.nanoseconds" with all nine digits (exact; "-" before negative values), and back.
std::string format_stamp_s(std::int64_t stamp_ns);
// Throws InputError (common/config_error.h) for text that is not [-]digits[.up to 9 digits].
std::int64_t parse_stamp_s(const std::string& text);

}  // namespace imu_lab
