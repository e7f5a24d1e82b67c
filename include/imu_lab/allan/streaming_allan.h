// Streaming Allan engine: one pass over time-stamped multi-channel samples, memory bounded
// independently of the run length, every Allan-family statistic available at any time.
//
// What is exact (equal to the batch reference, batch.h, on the same samples, to rounding):
// - m <= options.exact_max_averaging_factor: all nine statistics (ADEV, OADEV, MDEV, HDEV, OHDEV,
//   TDEV, TOTDEV, AKDEV, HKDEV) with their '#', noise type, EDF and bounds. TOTDEV's reflected end
//   terms need only the first and last 2m phase points of a segment (streaming_total_ends.h).
// - m > the limit: each statistic is the same estimator on the rate averaged over blocks of 2^L
//   samples at m / 2^L (decimated_batch.h is its batch reference), with that estimator's '#' and
//   EDF; TOTDEV there reflects the decimated series. ADEV/HDEV (non-overlapping) use only every m-th
//   phase point, which the decimated phase holds, so they stay equal to the exact ones.
// - Noise type: Stable32's rule for frequency data (evaluate_frequency), also for increments, so
//   the two input kinds give identical points.
//
// Memory per channel: per pyramid level L a phase window of 3 m_max + 1 points plus room for a
// block of 4096 / 2^L (at least 64) new ones (phase_block_points), and a head of 2 m_max doubles
// plus a few sums per tau; one history of at most
// 30 m_exact + 1 points twice (the B1 noise-type fallback, streaming_phase_history.h); one map
// entry per distinct segment length (a gap-free run holds one). About 0.95 MB per channel with the
// defaults (m_exact 1000, 10 taus per decade, tau up to 1e4 s at 1 kHz).
//
// Irregular input (see StreamingOptions): stamps are nanoseconds (the message header stamp).
// Duplicate and out-of-order stamps are dropped; a gap splits the run into segments whose sums
// are pooled (or any of them throws InputError under StampPolicy::kStop; the engine is then
// not to be used further). A NaN/Inf value is excluded and splits that channel's run only (the
// other channels keep theirs); it is never averaged in. Pooling: '#' and the sums add, EDFs add
// over segments (each at its own length), Krobka's mean difference is taken per segment.
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
  // sample_count samples at once, values row-major (options.channel_count per sample): the same
  // result, bit for bit, as pushing them one by one (either way the statistics run over blocks
  // of up to 4096 points per level, in one loop per averaging factor; the block boundaries depend
  // only on the data, never on how it was handed over or when snapshots were taken). Saves the
  // per-call overhead. Throws as push does.
  void push_block(const std::int64_t* stamps_ns, const double* values_row_major, std::size_t sample_count);

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
  void take(std::int64_t stamp_ns, const double* values);  // push without the flush
  bool has_unprocessed_points() const;
  void flush_channels();
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
