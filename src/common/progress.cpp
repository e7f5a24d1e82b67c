#include "imu_lab/common/progress.h"

#include <unistd.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <memory>

namespace imu_lab {

std::string format_eta(double remaining_s) {
  if (!std::isfinite(remaining_s) || remaining_s < 0.0) return "?";
  char text[48];
  if (remaining_s < 99.5) {
    std::snprintf(text, sizeof text, "%.0f s", remaining_s);
  } else if (remaining_s < 7200.0) {
    const long whole_s = std::lround(remaining_s);
    std::snprintf(text, sizeof text, "%ld min %02ld s", whole_s / 60, whole_s % 60);
  } else {
    std::snprintf(text, sizeof text, "%.1f h", remaining_s / 3600.0);
  }
  return text;
}

std::string progress_line(const std::string& tool, std::size_t done, std::size_t total, const std::string& unit,
                          double elapsed_s) {
  const double fraction = total > 0 ? std::min(1.0, static_cast<double>(done) / total) : 1.0;
  // Nothing done yet, or less than a second of it (the first message after the bag's opening),
  // says nothing about the rate.
  const double remaining_s = fraction > 0.0 && elapsed_s >= 1.0 ? elapsed_s * (1.0 - fraction) / fraction : NAN;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth);
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, "] %5.1f %% %zu/%zu ", 100.0 * fraction, done, total);
  return tool + ": [" + std::string(filled, '#') + std::string(kWidth - filled, ' ') + numbers + unit + ", ETA " +
         format_eta(remaining_s);
}

void ProgressBar::update(std::size_t done, std::size_t total) {
  if (total == 0) return;  // an empty pass draws nothing
  const auto now = Clock::now();
  if (done < previous_done_ || pass_finished_) {  // a new pass; an unfinished line is overwritten
    start_ = now;
    line_open_ = false;
    pass_finished_ = false;
  }
  previous_done_ = done;
  if (done < total && line_open_ && now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  const double elapsed_s = std::chrono::duration<double>(now - start_).count();
  const std::string line = progress_line(tool_, done, total, unit_, elapsed_s);
  // Spaces over what a longer previous line left.
  const std::size_t padding = drawn_length_ > line.size() ? drawn_length_ - line.size() : 0;
  std::fprintf(stderr, "\r%s%s", line.c_str(), std::string(padding, ' ').c_str());
  drawn_length_ = line.size();
  line_open_ = true;
  if (done >= total) {
    std::fprintf(stderr, "\n");
    line_open_ = false;
    pass_finished_ = true;
    drawn_length_ = 0;
  }
}

ProgressCallback terminal_progress(const std::string& tool, const std::string& unit, bool forced) {
  if (!forced && !::isatty(STDERR_FILENO)) return {};
  auto bar = std::make_shared<ProgressBar>(tool, unit);
  return [bar](std::size_t done, std::size_t total) { bar->update(done, total); };
}

}  // namespace imu_lab
