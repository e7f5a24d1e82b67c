// A streaming screen for level shifts: a step in a channel's level with no impulse (a sensor
// tilted on its bench, a bias that jumps), between the impulse screen and the streaming Allan
// engine. doc/impulse_screen.md, "Level shifts".
//
// At every sample c it compares the mean of the window_s after c with the mean of the window_s
// before it, per channel: D = mean[t_c, t_c + W) - mean[t_c - W, t_c). That difference is what
// the Allan variance at tau = W squares, so for stationary noise it has a scale of its own, here
// estimated online as a winsorised mean square of D itself (clipped at kLevelShiftClipSigma
// scales and divided by the clipped moment of a Gaussian, so that it is consistent and blind to
// the steps it looks for), forgetting with scale_memory_s. Screening starts once scale_warm_up_s
// of differences have been seen.
//
// Where |D| exceeds threshold_sigma scales in any channel a step is flagged. In the samples whose
// difference is flagged, plus guard_s on each side, every channel of the flagged channels' groups
// (channel_group_size: a triad; a tilt moves all three accelerometer axes, not the gyros) is set
// to NaN, which the engine excludes and at which it splits that channel's run: the step lies
// between two pooled segments of those channels instead of inside one, and the other channels
// are untouched. Each shift is recorded with its stamps and, per channel over the threshold, its
// size (D at the channel's peak) and its peak in scales; nothing is masked unrecorded.
//
// A stamp gap (more than gap_factor times the interval, the median of the first intervals) or a
// stamp that does not increase ends a segment: no window spans it, the held samples pass, and
// windows start again after it (a knock the impulse screen dropped is already a boundary).
// Values that are not finite or not usable stay out of the means and pass unchanged. Every sample
// passes, in order; the input is delayed by window_s + guard_s.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "imu_lab/allan/impulse_screen.h"

namespace imu_lab {
namespace allan {

constexpr double kLevelShiftClipSigma = 3.0;

struct LevelShiftScreenOptions {
  bool enabled = true;  // false: every sample passes at once
  std::size_t channel_count = 6;
  // Each side's window. On the static ADIS16405 units, 10 s windows put unit 4's tilt at 13.3 and
  // 17.9 scales (accelerometer y) and the largest excursion of the other units at 7.6.
  double window_s = 10.0;
  double threshold_sigma = 10.0;
  double guard_s = 1.0;  // masked before the first and after the last flagged difference
  double scale_warm_up_s = 300.0;
  double scale_memory_s = 3600.0;
  double gap_factor = 1.5;             // the engine's (streaming_options.h)
  std::size_t channel_group_size = 3;  // channels masked together (a triad), at most 32 groups
  std::size_t max_recorded_events = 1000;

  // Throws imu_lab::ConfigError naming the field when a value is unusable.
  void validate() const;
};

struct LevelShiftChannel {
  std::size_t channel = 0;
  double shift = 0.0;       // D at the channel's peak: the step, in the channel's units
  double peak_sigma = 0.0;  // that D in the channel's scales (signed)
  std::int64_t peak_stamp_ns = 0;
};

struct LevelShiftEvent {
  std::int64_t start_stamp_ns = 0;  // first masked sample
  std::int64_t end_stamp_ns = 0;    // last masked sample
  std::int64_t step_stamp_ns = 0;   // where the largest difference in scales lies: the step
  double peak_sigma = 0.0;
  std::size_t peak_channel = 0;
  std::int64_t masked_sample_count = 0;
  std::vector<LevelShiftChannel> channels;   // over the threshold, ascending index
  std::vector<std::size_t> masked_channels;  // set to NaN in the window (their groups), ascending
};

// channel_scales: the scale of D per channel.
struct LevelShiftReport : ScreenCounts {
  double window_s = 0.0;
  std::int64_t masked_sample_count = 0;             // samples with some channel set to NaN
  std::vector<std::int64_t> channel_masked_counts;  // per channel: values set to NaN
  std::vector<LevelShiftEvent> events;              // the first max_recorded_events, in time order
};

class LevelShiftScreen {
 public:
  // Throws imu_lab::ConfigError for unusable options.
  explicit LevelShiftScreen(const LevelShiftScreenOptions& options);

  // One sample of every channel; appends to `passed` the samples leaving the delay (each one, in
  // order, with the channels a shift masks set to NaN).
  void push(std::int64_t stamp_ns, const double* values, ScreenedSamples& passed);
  // Every sample of `input`, in order.
  void push(const ScreenedSamples& input, ScreenedSamples& passed);
  // End of input: what is held passes (an open shift closes).
  void finish(ScreenedSamples& passed);

  LevelShiftReport report() const;
  std::int64_t event_count() const { return counts_.event_count + (event_open_ ? 1 : 0); }
  // Samples pushed but not yet passed.
  std::size_t delayed_sample_count() const { return static_cast<std::size_t>(end_sequence() - release_); }

 private:
  struct ChannelState {
    double before_sum = 0.0;
    double after_sum = 0.0;
    std::int64_t before_count = 0;
    std::int64_t after_count = 0;
    double mean_square = 0.0;  // consistent winsorised mean square of D
    std::int64_t scale_count = 0;
    double peak_sigma = 0.0;  // of the open event
    double peak_shift = 0.0;
    std::int64_t peak_stamp_ns = 0;
  };

  std::size_t offset(std::int64_t sequence) const { return static_cast<std::size_t>(sequence - front_sequence_); }
  std::int64_t stamp_at(std::int64_t sequence) const { return stamps_ns_[offset(sequence)]; }
  double value_at(std::int64_t sequence, std::size_t c) const { return values_[offset(sequence) * channel_count_ + c]; }
  std::int64_t end_sequence() const { return front_sequence_ + static_cast<std::int64_t>(stamps_ns_.size()); }

  bool segment_boundary(std::int64_t stamp_ns);
  void evaluate_centre();
  void advance_centre();
  void update_scale(std::size_t channel, double difference, std::int64_t step_ns);
  void open_event(std::int64_t sequence);
  void mask(std::int64_t sequence);
  LevelShiftEvent event_as_it_stands() const;
  void close_event();
  void release(bool all, ScreenedSamples& passed);
  void end_segment(ScreenedSamples& passed);

  LevelShiftScreenOptions options_;
  std::size_t channel_count_;
  std::int64_t window_ns_;
  std::int64_t guard_ns_;
  std::vector<ChannelState> channels_;
  std::vector<std::int64_t> channel_masked_counts_;

  // Held samples; entry i is sequence front_sequence_ + i.
  std::deque<std::int64_t> stamps_ns_;
  std::deque<double> values_;
  std::deque<std::uint32_t> masks_;  // per held sample: the groups set to NaN (bit g: group g)
  std::int64_t front_sequence_ = 0;
  std::int64_t before_begin_ = 0;  // first sample of the window before the centre
  std::int64_t centre_ = 0;        // next sample whose difference is taken
  std::int64_t release_ = 0;       // next sample to pass
  std::int64_t segment_start_ns_ = 0;
  bool segment_empty_ = true;

  std::vector<std::int64_t> first_intervals_ns_;
  std::int64_t interval_ns_ = 0;  // 0 until the first intervals are in
  std::int64_t last_stamp_ns_ = 0;
  std::int64_t last_scaled_stamp_ns_ = 0;
  bool scaled_in_segment_ = false;
  std::int64_t scaled_ns_ = 0;  // time covered by the differences seen
  std::vector<double> scratch_differences_;

  ScreenCounts counts_;
  std::int64_t masked_count_ = 0;

  bool event_open_ = false;
  LevelShiftEvent event_;
  std::uint32_t event_groups_ = 0;
  std::int64_t last_flag_stamp_ns_ = 0;
  std::vector<LevelShiftEvent> events_;
};

}  // namespace allan
}  // namespace imu_lab
