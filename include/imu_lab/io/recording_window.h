// Which part of a recording a tool reads, and where the split files of one recording hand over
// to each other: plain values the bag reader (ros_io/bag/imu_bag_reader.h) fills and the reports print.
// See doc/recordings.md.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace imu_lab {
namespace io {

// The part of a recording to use, in seconds from the first header stamp of the topic read
// (e.g. leave out a warm-up with start_s); both ends included.
struct TimeWindow {
  double start_s = 0.0;
  double end_s = std::numeric_limits<double>::infinity();
  bool is_whole() const { return start_s <= 0.0 && end_s == std::numeric_limits<double>::infinity(); }
};
// Empty if usable, otherwise why not (start negative or not finite, end not after start).
std::string time_window_problem(const TimeWindow& window);
// "whole recording" or "from 600 s to 3600 s after the first stamp".
std::string describe_time_window(const TimeWindow& window);

// Where one file of a recording hands over to the next, on the topic last streamed.
struct FileJoin {
  std::string before_path, after_path;
  double gap_s = 0.0;  // after's first header stamp minus before's last
};

// "joins between split files: a.bag -> b.bag 0.01 s, ..." (empty for none).
std::string describe_joins(const std::vector<FileJoin>& joins);

}  // namespace io
}  // namespace imu_lab
