// Progress of a long pass on a terminal, shared by every tool that can run for more than about a
// minute: one line on stderr, redrawn at most five times a second,
//   "navigate: [###############               ]  50.0 % 5000/10000 messages, ETA 1 min 05 s"
// The ETA assumes the rest goes at the average rate so far ("?" for the first second).
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace imu_lab {

// "42 s" below 100 s, "12 min 05 s" below 2 h, "3.4 h" above; "?" before anything is done.
std::string format_eta(double remaining_s);

// The line without its leading carriage return.
std::string progress_line(const std::string& tool, std::size_t done, std::size_t total, const std::string& unit,
                          double elapsed_s);

class ProgressBar {
 public:
  ProgressBar(std::string tool, std::string unit) : tool_(std::move(tool)), unit_(std::move(unit)) {}
  // A `done` below the previous one, or any after a finished pass, starts a new pass (a tool
  // reading a second topic): a finished line stays, an unfinished one (a read that stopped at
  // what it sought) is overwritten, and the clock starts again.
  void update(std::size_t done, std::size_t total);

 private:
  using Clock = std::chrono::steady_clock;
  std::string tool_, unit_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_{};
  std::size_t previous_done_ = 0;
  bool line_open_ = false;
  bool pass_finished_ = false;
  std::size_t drawn_length_ = 0;  // of the line on screen, while it is open
};

using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

// A ProgressBar's update when stderr is a terminal or `forced`; otherwise empty (no output), so
// logs and pipes stay clean.
ProgressCallback terminal_progress(const std::string& tool, const std::string& unit, bool forced = false);

}  // namespace imu_lab
