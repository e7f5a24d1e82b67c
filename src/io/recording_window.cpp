#include "imu_lab/io/recording_window.h"

#include <cmath>
#include <cstdio>

namespace imu_lab {
namespace io {

std::string time_window_problem(const TimeWindow& window) {
  if (!std::isfinite(window.start_s) || window.start_s < 0.0) {
    return "the window's start must be a number of seconds >= 0 from the first stamp";
  }
  if (std::isnan(window.end_s) || !(window.end_s > window.start_s)) return "the window's end must be after its start";
  return "";
}

std::string describe_time_window(const TimeWindow& window) {
  if (window.is_whole()) return "whole recording";
  char text[96];
  if (std::isinf(window.end_s)) {
    std::snprintf(text, sizeof text, "from %.9g s after the first stamp to the end", window.start_s);
  } else {
    std::snprintf(text, sizeof text, "from %.9g s to %.9g s after the first stamp", window.start_s, window.end_s);
  }
  return text;
}

std::string describe_joins(const std::vector<FileJoin>& joins) {
  if (joins.empty()) return "";
  std::string text = "joins between split files (the gap is the time between the stamps either side):";
  char gap[48];
  for (const FileJoin& join : joins) {
    std::snprintf(gap, sizeof gap, "%.6g s", join.gap_s);
    text += "\n  " + join.before_path + " -> " + join.after_path + ": gap " + gap;
  }
  return text;
}

}  // namespace io
}  // namespace imu_lab
