// A streaming screen for knocks and spikes between a sample reader and the streaming Allan engine.
//
// Each channel's deviation from its local level (the mean of its previous level_sample_count
// finite values) is compared with a robust scale of that same deviation, estimated online: the
// mean of the squared deviations clipped at kScaleClipSigma scales (a winsorised variance,
// iterated from the plain RMS over the first scale_warm_up_sample_count samples, then updated
// with exponential forgetting), divided by its expectation for Gaussian noise so that it is
// consistent. Unlike a median absolute deviation it is not coarse on quantised output: every
// deviation contributes its own size, so a scale of about one LSB is estimated to a fraction of
// it. Because the scale is measured on the very statistic that is thresholded, correlated noise
// (a sensor's anti-alias filter) and the level's own noise are accounted for.
//
// A sample whose deviation exceeds threshold_sigma scales in any channel is flagged. Every
// detection is widened into an event window: guard_before_s before the first flagged sample (a
// delay line holds that much of the input), guard_after_s after the last; a flag inside the
// window extends it, and two windows less than merge_gap_s apart are one event (with the samples
// between them). The samples of a window are dropped, so the engine sees a stamp gap there and,
// under its split-and-pool policy, starts a new segment: a knock that leaves a step in the bias
// becomes a segment boundary, not only samples missing. A window always drops at least floor(gap_factor) + 2 samples,
// so the hole exceeds the engine's gap_factor * tau0 whatever the rate. Each event is recorded with its stamps, the
// channels over the threshold and their peaks; nothing is dropped unrecorded.
//
// Values that are not finite are not screened and never enter a level or a scale; they pass to
// the engine (which excludes them). Stamps are used as given: the screen keeps the input order
// and leaves duplicate or out-of-order stamps to the engine.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace imu_lab {
namespace allan {

// The deviations are clipped at this many scales in the scale's estimate: efficient for Gaussian
// noise (kScaleClipSigma^2 * P(|z| > 3) adds little) and blind to spikes.
constexpr double kScaleClipSigma = 3.0;

struct ImpulseScreenOptions {
  bool enabled = true;  // false: every sample passes at once, nothing is estimated
  std::size_t channel_count = 6;

  // Default 12 scales. Gaussian noise exceeds 12 sigma with probability 3.6e-33 per value: over
  // 6 channels at 400 Hz that is about 3e-26 false events per hour (even 7 would give 2e-5).
  // The bound comes from real sensors instead: static ADIS16405 records (three units, 2.8 h at
  // 100 Hz each) have isolated one-sample accelerometer excursions of up to 10-11 scales in
  // every unit, a property of the output rather than a disturbance, while the smallest knock of
  // the knocked unit reaches 13.6 and its two large ones 79 and 124 (doc/impulse_screen.md).
  double threshold_sigma = 12.0;
  // A knock's onset is abrupt but its first samples can stay under the threshold; the ringing
  // after it was seen up to 0.6 s after the last flagged sample on those records.
  double guard_before_s = 0.25;
  double guard_after_s = 1.0;
  // Between two windows closer than this the few samples left would make a segment too short to
  // matter for any tau, while splitting the event would hide that it was one disturbance (the
  // knocked unit's first disturbance flags samples at 117.10 s, 117.69 s and 118.99 s).
  double merge_gap_s = 1.0;

  std::size_t level_sample_count = 16;            // the local level: mean of this many previous values
  std::size_t scale_warm_up_sample_count = 1000;  // the first scale: from this many deviations
  // The scale then forgets with this time constant (in samples): its relative error is about
  // 1 / sqrt(2 * 65536) = 0.3 %, and it follows a slow change of the noise.
  std::size_t scale_memory_sample_count = 65536;
  // The engine's gap_factor (streaming_options.h): each window drops enough samples to exceed it.
  double gap_factor = 1.5;
  // Events kept with their details (all are counted).
  std::size_t max_recorded_events = 1000;

  // Throws imu_lab::ConfigError naming the field when a value is unusable.
  void validate() const;
};

struct ImpulseChannelPeak {
  std::size_t channel = 0;
  double peak_sigma = 0.0;  // signed deviation from the level, in the channel's scales
  std::int64_t peak_stamp_ns = 0;
};

struct ImpulseEvent {
  std::int64_t start_stamp_ns = 0;  // first dropped sample
  std::int64_t end_stamp_ns = 0;    // last dropped sample
  std::int64_t onset_stamp_ns = 0;  // first sample over the threshold: when the knock began
  std::int64_t peak_stamp_ns = 0;   // the sample with the largest |deviation| over all channels
  double peak_sigma = 0.0;          // that deviation (signed), in its channel's scales
  std::size_t peak_channel = 0;
  std::int64_t flagged_sample_count = 0;     // samples over the threshold in some channel
  std::int64_t dropped_sample_count = 0;     // samples of the window (none of them reaches the engine)
  std::vector<ImpulseChannelPeak> channels;  // the channels over the threshold, ascending index
};

// What a screen before the engine counts of its run (this one and level_shift_screen.h's).
struct ScreenCounts {
  bool enabled = false;
  double threshold_sigma = 0.0;
  std::int64_t input_sample_count = 0;
  std::int64_t passed_sample_count = 0;  // handed on
  std::int64_t event_count = 0;          // closed events (a report adds an open one)
  std::int64_t first_stamp_ns = 0;       // of the input, for stamps relative to its start
  // Per channel the scale of the screened statistic (the channel's units); 0 until estimated
  // (and for a channel that has not varied). Filled by report().
  std::vector<double> channel_scales;

  ScreenCounts() = default;
  ScreenCounts(bool screen_enabled, double screen_threshold_sigma)
      : enabled(screen_enabled), threshold_sigma(screen_threshold_sigma) {}

  void count_input(std::int64_t stamp_ns) {
    if (input_sample_count++ == 0) first_stamp_ns = stamp_ns;
  }
};

// A report's common part (Report derives from ScreenCounts and lists `events`): the counts, the
// scale per channel from each channel state's mean_square, and the recorded events with, while
// one is open, that one as it stands (counted, and listed while there is room below max_recorded).
template <typename Report, typename Channels, typename Events, typename AsItStands>
Report screen_report(const ScreenCounts& counts, const Channels& channels, const Events& events, bool open,
                     AsItStands as_it_stands, std::size_t max_recorded) {
  Report report;
  static_cast<ScreenCounts&>(report) = counts;
  for (const auto& channel : channels) report.channel_scales.push_back(std::sqrt(channel.mean_square));
  report.events = events;
  if (open) {
    ++report.event_count;
    if (report.events.size() < max_recorded) report.events.push_back(as_it_stands());
  }
  return report;
}

struct ImpulseScreenReport : ScreenCounts {
  std::int64_t dropped_sample_count = 0;  // in event windows
  std::vector<ImpulseEvent> events;       // the first max_recorded_events, in time order
};

// The samples that passed, in input order, row-major like StreamingAllan::push_block wants.
struct ScreenedSamples {
  std::vector<std::int64_t> stamps_ns;
  std::vector<double> values;
  std::size_t size() const { return stamps_ns.size(); }
  bool empty() const { return stamps_ns.empty(); }
  void clear() {
    stamps_ns.clear();
    values.clear();
  }
};

// Counts one input sample; a screen that is off passes it at once and says so (true).
inline bool passed_unscreened(bool enabled, std::int64_t stamp_ns, const double* values, std::size_t channel_count,
                              ScreenCounts& counts, ScreenedSamples& passed) {
  counts.count_input(stamp_ns);
  if (enabled) return false;
  passed.stamps_ns.push_back(stamp_ns);
  passed.values.insert(passed.values.end(), values, values + channel_count);
  ++counts.passed_sample_count;
  return true;
}

class ImpulseScreen {
 public:
  // Throws imu_lab::ConfigError for unusable options.
  explicit ImpulseScreen(const ImpulseScreenOptions& options);

  // One sample of every channel (options.channel_count values). Appends to `passed` the samples
  // that leave the delay line (not necessarily this one, and possibly several).
  void push(std::int64_t stamp_ns, const double* values, ScreenedSamples& passed);
  // End of input: screens what the delay line holds and appends what passes. An event still
  // open ends at the last sample. Pushing after finish() starts a new delay line.
  void finish(ScreenedSamples& passed);

  ImpulseScreenReport report() const;
  // Events so far, an open one included (cheap; never decreases).
  std::int64_t event_count() const { return counts_.event_count + (window_open_ ? 1 : 0); }
  const ImpulseScreenOptions& options() const { return options_; }
  // Samples pushed but not yet passed or dropped.
  std::size_t delayed_sample_count() const { return line_size_; }

 private:
  struct ChannelState {
    std::vector<double> level_ring;  // the last finite values
    std::size_t level_next = 0;
    std::size_t level_count = 0;
    double level_sum = 0.0;
    double mean_square = 0.0;  // consistent clipped mean square of the deviation; 0: not screened yet
    std::int64_t scale_sample_count = 0;
  };
  // The window being built (kept after it closes, so that a touching one can reopen it).
  struct Window {
    std::int64_t last_flag_stamp_ns = 0;
    std::int64_t last_sequence = -2;  // last dropped sample
    ImpulseEvent event;
    std::vector<double> peak_sigma;  // per channel, signed
    std::vector<std::int64_t> peak_stamp_ns;
    bool recorded = false;  // the closed event is in events_
  };

  // The delay line: a ring of samples in input order; entry i is sequence front_sequence_ + i.
  std::size_t line_index(std::size_t i) const { return (line_head_ + i) & (line_capacity_ - 1); }
  void line_push(std::int64_t stamp_ns, const double* values, const double* deviations);
  void line_grow();

  void level_and_deviation(const double* values, double* deviations);
  void initialise_scales();
  void update_scale(std::size_t channel, double deviation);
  double sigmas(std::size_t channel, double deviation, double value) const;
  void process(std::size_t i);
  void open_window(std::size_t i);
  void drop(std::size_t i);
  ImpulseEvent window_event() const;  // the window's event as it stands
  void close_window();
  void release(bool all, ScreenedSamples& passed);

  ImpulseScreenOptions options_;
  std::size_t channel_count_;
  std::int64_t guard_before_ns_;
  std::int64_t guard_after_ns_;
  std::int64_t merge_gap_ns_;
  std::int64_t min_dropped_samples_;
  double scale_weight_floor_;  // 1 / scale_memory_sample_count
  double threshold_square_;    // threshold_sigma^2
  std::vector<ChannelState> channels_;

  std::vector<std::int64_t> line_stamps_ns_;
  std::vector<double> line_values_;
  std::vector<double> line_deviations_;
  std::vector<std::uint8_t> line_dropped_;
  std::size_t line_capacity_ = 0;
  std::size_t line_head_ = 0;
  std::size_t line_size_ = 0;
  std::size_t processed_ = 0;  // entries [0, processed_) of the line are screened
  std::int64_t front_sequence_ = 0;
  std::int64_t latest_processed_stamp_ns_ = 0;
  std::vector<double> scratch_deviations_;

  bool scales_ready_ = false;
  ScreenCounts counts_;
  std::int64_t dropped_count_ = 0;

  bool window_open_ = false;
  Window window_;
  std::vector<ImpulseEvent> events_;
};

}  // namespace allan
}  // namespace imu_lab
