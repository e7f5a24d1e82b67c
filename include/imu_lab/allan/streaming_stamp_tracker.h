// Classifies each stamp against the previous accepted one once tau0 is fixed, and keeps the
// jitter statistics and the record of gaps, duplicates and out-of-order stamps.
#pragma once

#include <cstdint>

#include "imu_lab/allan/checkpoint_codec.h"
#include "imu_lab/allan/streaming_compensated_sum.h"
#include "imu_lab/allan/streaming_options.h"
#include "imu_lab/allan/streaming_report.h"

namespace imu_lab {
namespace allan {

enum class StampVerdict { kFirst, kNext, kGap, kDuplicate, kOutOfOrder };

class StampTracker {
 public:
  StampTracker() = default;
  StampTracker(std::int64_t tau0_ns, double gap_factor, StampPolicy policy);

  // Under StampPolicy::kStop an irregular stamp throws imu_lab::InputError (state unchanged).
  StampVerdict classify(std::int64_t stamp_ns, std::int64_t sample_index);

  std::int64_t tau0_ns() const { return tau0_ns_; }
  std::int64_t last_stamp_ns() const { return last_stamp_ns_; }
  void fill(TimingReport& report) const;

  void save(BinaryWriter& out) const;
  void load(BinaryReader& in);

 private:
  void record(StampEventKind kind, std::int64_t sample_index, std::int64_t stamp_ns);

  std::int64_t tau0_ns_ = 0;
  double gap_threshold_ns_ = 0.0;
  StampPolicy policy_ = StampPolicy::kSplitAndPool;
  bool has_last_ = false;
  std::int64_t last_stamp_ns_ = 0;
  std::int64_t accepted_count_ = 0;
  std::int64_t regular_interval_count_ = 0;
  CompensatedSum squared_deviation_s2_;
  double max_deviation_s_ = 0.0;
  std::int64_t gap_count_ = 0;
  CompensatedSum gap_time_s_;
  std::int64_t duplicate_count_ = 0;
  std::int64_t out_of_order_count_ = 0;
  std::vector<StampEvent> events_;
};

}  // namespace allan
}  // namespace imu_lab
