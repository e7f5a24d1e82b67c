// Constant-rate plateaus of a rate-table recording, found automatically from the rate about the
// table axis: non-overlapping windows are averaged; a window is steady when its mean differs from
// both neighbours' by at most a threshold (a multiple of the window-mean noise, estimated robustly
// from the median absolute difference of consecutive window means, so the few windows of the
// transitions do not inflate it); a plateau is a run of steady windows whose spread stays within
// twice the threshold (a slow ramp is trimmed from the run's ends until it does), shortened by a
// guard at each end (at least one window: the windows next to a transition may hold a sub-threshold
// piece of it) and kept when at least min_duration_s remain. See doc/rate_table.md.
#pragma once

#include <cstddef>
#include <vector>

namespace imu_lab {
namespace rate_table {

struct PlateauOptions {
  double window_s = 1.0;
  double threshold_sigmas = 6.0;  // steady: |difference of window means| <= this many noise sigmas
  double threshold_rad_s = 0.0;   // > 0: use this threshold instead
  double guard_s = 1.0;           // dropped at each end of a plateau (at least one window)
  double min_duration_s = 10.0;   // shorter plateaus (after the guards) are ignored
};

struct Plateau {
  std::size_t begin = 0;  // first sample
  std::size_t end = 0;    // one past the last sample
  double start_s = 0.0;   // stamp of the first sample
  double duration_s = 0.0;
  double level_rad_s = 0.0;  // mean rate about the table axis over [begin, end)
  std::size_t size() const { return end - begin; }
};

struct PlateauDetection {
  std::vector<Plateau> plateaus;    // in time order
  double window_s = 0.0;            // the realised window (a whole number of samples)
  double window_noise_rad_s = 0.0;  // robust sigma of a window mean
  double threshold_rad_s = 0.0;
};

// stamps_s increasing, rate_rad_s the rate about the table axis (same length). Throws InputError
// if there are fewer than three windows or the stamps do not increase.
PlateauDetection detect_plateaus(const std::vector<double>& stamps_s, const std::vector<double>& rate_rad_s,
                                 const PlateauOptions& options);

}  // namespace rate_table
}  // namespace imu_lab
