// Streaming Allan engine: one pass over time-stamped multi-channel samples, memory bounded
// independently of the run length, every Allan-family statistic available at any time.
//
// Exactness: fully-overlapping estimates at m <= options.exact_max_averaging_factor equal the
// batch reference (batch.h) on the same samples. Beyond, each statistic is the same estimator on the
// rate averaged over blocks of 2^L samples (decimated_batch.h is its batch reference), with the term
// count and EDF of that decimated estimator. TOTDEV is exact on the same terms: its reflected end
// terms come from a head buffer and the phase ring of each segment (streaming_total_ends.h).
// Non-overlapping ADEV/HDEV beyond the limit equal the exact ones (the decimated phase holds
// every point they use).
//
// Irregular input (see StreamingOptions): duplicate and out-of-order stamps are dropped, a gap
// splits the run into segments whose sums are pooled (or any of them throws InputError under
// StampPolicy::kStop). A NaN/Inf value is excluded and splits that channel's run only (the
// other channels keep theirs); it is never averaged in.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "imu_lab/allan/streaming_channel.h"
#include "imu_lab/allan/streaming_options.h"
#include "imu_lab/allan/streaming_snapshot.h"
#include "imu_lab/allan/streaming_stamp_tracker.h"
#include "imu_lab/allan/streaming_warm_up.h"

namespace imu_lab {
namespace allan {

class StreamingAllan {
 public:
  // Throws imu_lab::ConfigError for unusable options.
  explicit StreamingAllan(const StreamingOptions& options);

  // One sample of every channel, in options.channel_count order, with its header stamp.
  // Throws imu_lab::InputError for a wrong value count, and for irregular stamps under kStop.
  void push(std::int64_t stamp_ns, const double* values, std::size_t value_count);
  void push(std::int64_t stamp_ns, const std::vector<double>& values);

  // The curves and reports as they stand; after the last push this is the final result.
  StreamingSnapshot snapshot() const;

  // The whole state, written atomically (checkpoint.h); resume with load_checkpoint and keep
  // pushing from the sample after last_stamp_ns(). Loading throws imu_lab::InputError for a
  // file of another version, a corrupted or a truncated one.
  void save_checkpoint(const std::string& path) const;
  static StreamingAllan load_checkpoint(const std::string& path);

  const StreamingOptions& options() const { return options_; }
  bool warmed_up() const { return warmed_up_; }
  std::int64_t input_sample_count() const { return input_sample_count_; }
  std::int64_t last_stamp_ns() const { return last_stamp_ns_; }  // last pushed (accepted or not)
  // Heap and object bytes of the whole state: constant after warm-up for a gap-free run.
  std::size_t state_size_bytes() const;

 private:
  void finish_warm_up();
  std::size_t history_capacity() const;
  void accept(std::int64_t stamp_ns, const double* values, std::int64_t sample_index);
  std::string serialise() const;
  void deserialise_state(BinaryReader& in);

  StreamingOptions options_;
  WarmUpBuffer warm_up_;
  bool warmed_up_ = false;
  std::int64_t input_sample_count_ = 0;
  std::int64_t last_stamp_ns_ = 0;
  StampTracker stamps_;
  std::vector<ChannelAccumulator> channels_;
  std::vector<ChannelReport> channel_reports_;
};

}  // namespace allan
}  // namespace imu_lab
