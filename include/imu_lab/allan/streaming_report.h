// What the streaming engine reports about its input besides the curves: the sample period it
// settled on, how regular the stamps were, and every irregularity it met.
#pragma once

#include <cstdint>
#include <vector>

namespace imu_lab {
namespace allan {

enum class StampEventKind {
  kGap,         // interval above gap_factor * tau0: the run was split there
  kDuplicate,   // same stamp as the previous accepted sample: sample dropped
  kOutOfOrder,  // stamp before the previous accepted sample: sample dropped
};

struct StampEvent {
  StampEventKind kind = StampEventKind::kGap;
  std::int64_t sample_index = 0;       // 0-based position of the offending sample in the input
  std::int64_t previous_stamp_ns = 0;  // last accepted stamp
  std::int64_t stamp_ns = 0;           // the offending sample's stamp
};

struct TimingReport {
  double tau0_s = 0.0;                     // median interval of the warm-up window
  double interval_rms_deviation_s = 0.0;   // RMS of (interval - tau0) over regular intervals
  double interval_max_deviation_s = 0.0;   // max |interval - tau0| over regular intervals
  std::int64_t input_sample_count = 0;     // everything pushed
  std::int64_t accepted_sample_count = 0;  // pushed minus dropped stamps
  std::int64_t gap_count = 0;
  double gap_time_s = 0.0;  // sum over gaps of (interval - tau0)
  std::int64_t duplicate_count = 0;
  std::int64_t out_of_order_count = 0;
  std::vector<StampEvent> events;  // the first kMaxRecordedStampEvents, in input order
};

constexpr std::size_t kMaxRecordedStampEvents = 100;

struct ChannelReport {
  double offset = 0.0;                   // removed before accumulating (mean of the warm-up window)
  std::int64_t finite_sample_count = 0;  // accumulated
  // NaN/Inf or beyond kLargestUsableImuValue (common/usable_imu_values.h): excluded, each one splits the
  // channel's run (the sums would otherwise overflow and spoil every later point)
  std::int64_t non_finite_count = 0;
  std::int64_t first_non_finite_sample_index = -1;
  std::int64_t last_non_finite_sample_index = -1;
  std::int64_t segment_count = 0;  // runs of consecutive accepted finite samples
};

}  // namespace allan
}  // namespace imu_lab
