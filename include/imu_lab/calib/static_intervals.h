// Static intervals of a calibration recording, found automatically: the IMU is at rest where the
// mean angular rate over short windows stays near the recording's resting level. Used in both
// modes (a table schedule says what the orientations are, not exactly when the table stopped).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "imu_lab/io/imu_records.h"

namespace imu_lab {
namespace calib {

struct StaticInterval {
  std::size_t begin = 0;  // first sample
  std::size_t end = 0;    // one past the last sample
  std::size_t size() const { return end - begin; }
};

struct StaticDetectionOptions {
  double window_s = 0.25;         // windows whose mean rate is tested
  double min_duration_s = 2.0;    // shorter rests are ignored (hesitations while turning)
  double threshold_sigmas = 6.0;  // threshold = this many window-mean noise sigmas + 2 |Earth rate|
  double threshold_rad_s = 0.0;   // > 0: use this threshold instead
  // The resting level (median window mean) is a gyro bias plus Earth rate; above this the
  // recording has no rests (e.g. a continuous rotation) rather than a huge bias.
  double max_resting_rate_rad_s = 0.02;
};

struct StaticDetection {
  std::vector<StaticInterval> intervals;  // in time order; one window trimmed at each end
  double window_s = 0.0;
  double window_noise_rad_s = 0.0;  // robust sigma of a window's mean rate at rest
  double threshold_rad_s = 0.0;     // |window mean - resting level| below this counts as rest
  Eigen::Vector3d resting_level_rad_s = Eigen::Vector3d::Zero();
};

// Throws InputError if the samples are too few for one window or the stamps are not increasing.
StaticDetection detect_static_intervals(const std::vector<io::ImuRecord>& samples,
                                        const StaticDetectionOptions& options);

}  // namespace calib
}  // namespace imu_lab
