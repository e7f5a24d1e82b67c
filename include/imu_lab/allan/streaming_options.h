// Configuration of the streaming Allan engine (StreamingAllan).
#pragma once

#include <cstddef>

namespace imu_lab {
namespace allan {

// What one pushed value means.
enum class InputKind {
  kFrequency,  // a rate sample y (e.g. rad/s): the mean rate over the sample interval
  kIncrement,  // a phase increment (e.g. rad per sample, a ring-laser gyro's pulses * weight)
};

// What to do with a gap (interval above gap_factor * tau0), a duplicate or an out-of-order stamp.
enum class StampPolicy {
  kSplitAndPool,  // gaps split the run into segments whose sums are pooled; bad stamps are dropped
  kStop,          // throw imu_lab::InputError naming the stamp at the first irregularity
};

enum class TauSpacing {
  kLogarithmic,  // round(10^(i / points_per_decade)), duplicates removed
  kEveryM,       // every m from 1 (meant for small data); beyond the exact limit every m a level tells apart
};

constexpr double kMaxPointsPerDecade = 1000.0;
// Per channel the state holds about 65 doubles per unit of the exact limit (the B1 history, the
// rings and heads of the levels): 2^20 is about 0.5 GB.
constexpr int kMaxExactAveragingFactor = 1 << 20;
// Every-m spacing keeps every factor up to the limit (and half as many per level above it).
constexpr int kMaxEveryMExactFactor = 4096;

struct StreamingOptions {
  std::size_t channel_count = 6;
  InputKind input_kind = InputKind::kFrequency;

  TauSpacing tau_spacing = TauSpacing::kLogarithmic;
  double points_per_decade = 10.0;
  double max_tau_s = 1.0e4;

  // Fully-overlapping estimates are exact up to this averaging factor; beyond it every statistic
  // is the same estimator run on rate averaged over 2^L samples (one pyramid level per octave).
  int exact_max_averaging_factor = 1000;

  // tau0 is the median stamp interval over the first warm_up_sample_count samples, then fixed;
  // each channel's offset (removed before accumulating, see doc/models.md) is the mean of its
  // finite values over the same window.
  std::size_t warm_up_sample_count = 1000;

  double gap_factor = 1.5;  // an interval above gap_factor * tau0 is a gap
  StampPolicy stamp_policy = StampPolicy::kSplitAndPool;

  double confidence = 0.683;  // two-sided, for the chi-squared bounds

  // Throws imu_lab::ConfigError naming the field when a value is unusable.
  void validate() const;
};

}  // namespace allan
}  // namespace imu_lab
