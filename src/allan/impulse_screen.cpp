#include "imu_lab/allan/impulse_screen.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/robust_statistics.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/common/usable_imu_values.h"

namespace imu_lab {
namespace allan {
namespace {

void require(bool condition, const char* key, const std::string& problem) {
  if (!condition) throw ConfigError("ImpulseScreenOptions", key, problem);
}

const double kClippedMoment = clipped_gaussian_second_moment(kScaleClipSigma);

// A deviation below this fraction of the value is floating-point rounding, never an event (a
// noise-free channel's level differs from its values by an ulp or so).
constexpr double kRoundingFraction = 1e-12;

// The delay line holds at most this many samples whatever the stamps do (a run of equal stamps
// would otherwise never leave the guard): about 7 MB with 6 channels.
constexpr std::size_t kMaxDelayedSamples = std::size_t{1} << 16;

}  // namespace

void ImpulseScreenOptions::validate() const {
  require(channel_count >= 1, "channel_count", "must be at least 1");
  require(
      std::isfinite(threshold_sigma) && threshold_sigma > kScaleClipSigma, "threshold_sigma",
      "must be a number above " + std::to_string(kScaleClipSigma) + " (scales of the deviation; 12 is the default)");
  require(std::isfinite(guard_before_s) && guard_before_s >= 0.0 && guard_before_s <= 60.0, "guard_before_s",
          "must lie between 0 and 60 s");
  require(std::isfinite(guard_after_s) && guard_after_s >= 0.0 && guard_after_s <= 3600.0, "guard_after_s",
          "must lie between 0 and 3600 s");
  require(std::isfinite(merge_gap_s) && merge_gap_s >= 0.0 && merge_gap_s <= 60.0, "merge_gap_s",
          "must lie between 0 and 60 s");
  require(level_sample_count >= 1 && level_sample_count <= 4096, "level_sample_count", "must lie between 1 and 4096");
  require(scale_warm_up_sample_count >= 16 && scale_warm_up_sample_count <= kMaxDelayedSamples / 2,
          "scale_warm_up_sample_count", "must lie between 16 and " + std::to_string(kMaxDelayedSamples / 2));
  require(scale_memory_sample_count >= scale_warm_up_sample_count, "scale_memory_sample_count",
          "must be at least scale_warm_up_sample_count");
  require(std::isfinite(gap_factor) && gap_factor > 1.0 && gap_factor <= 1e6, "gap_factor",
          "must be above 1 (the engine's, 1.5 is usual)");
}

ImpulseScreen::ImpulseScreen(const ImpulseScreenOptions& options)
    : options_(options), counts_(options.enabled, options.threshold_sigma) {
  options_.validate();
  channel_count_ = options_.channel_count;
  guard_before_ns_ = stamp_ns_from_seconds(options_.guard_before_s);
  guard_after_ns_ = stamp_ns_from_seconds(options_.guard_after_s);
  merge_gap_ns_ = stamp_ns_from_seconds(options_.merge_gap_s);
  threshold_square_ = options_.threshold_sigma * options_.threshold_sigma;
  // A hole of floor(gap_factor) + 3 intervals is above gap_factor * tau0 even with some jitter.
  min_dropped_samples_ = static_cast<std::int64_t>(std::floor(options_.gap_factor)) + 2;
  scale_weight_floor_ = 1.0 / static_cast<double>(options_.scale_memory_sample_count);
  channels_.resize(channel_count_);
  for (ChannelState& channel : channels_) channel.level_ring.assign(options_.level_sample_count, 0.0);
  scratch_deviations_.resize(channel_count_);
  window_.peak_sigma.assign(channel_count_, 0.0);
  window_.peak_stamp_ns.assign(channel_count_, 0);
  line_capacity_ = 64;
  while (line_capacity_ <= options_.scale_warm_up_sample_count) line_capacity_ *= 2;
  line_stamps_ns_.resize(line_capacity_);
  line_values_.resize(line_capacity_ * channel_count_);
  line_deviations_.resize(line_capacity_ * channel_count_);
  line_dropped_.resize(line_capacity_);
}

void ImpulseScreen::push(std::int64_t stamp_ns, const double* values, ScreenedSamples& passed) {
  if (passed_unscreened(options_.enabled, stamp_ns, values, channel_count_, counts_, passed)) return;
  level_and_deviation(values, scratch_deviations_.data());
  line_push(stamp_ns, values, scratch_deviations_.data());
  if (!scales_ready_) {
    if (line_size_ < options_.scale_warm_up_sample_count) return;
    initialise_scales();
  }
  while (processed_ < line_size_) process(processed_++);
  release(false, passed);
}

void ImpulseScreen::finish(ScreenedSamples& passed) {
  if (!options_.enabled) return;
  if (!scales_ready_) initialise_scales();
  while (processed_ < line_size_) process(processed_++);
  if (window_open_) close_window();
  release(true, passed);
}

void ImpulseScreen::line_push(std::int64_t stamp_ns, const double* values, const double* deviations) {
  if (line_size_ == line_capacity_) line_grow();
  const std::size_t index = line_index(line_size_);
  line_stamps_ns_[index] = stamp_ns;
  std::copy(values, values + channel_count_, line_values_.begin() + index * channel_count_);
  std::copy(deviations, deviations + channel_count_, line_deviations_.begin() + index * channel_count_);
  line_dropped_[index] = 0;
  ++line_size_;
}

void ImpulseScreen::line_grow() {
  const std::size_t capacity = line_capacity_ * 2;
  std::vector<std::int64_t> stamps(capacity);
  std::vector<double> values(capacity * channel_count_);
  std::vector<double> deviations(capacity * channel_count_);
  std::vector<std::uint8_t> dropped(capacity);
  for (std::size_t i = 0; i < line_size_; ++i) {
    const std::size_t from = line_index(i);
    stamps[i] = line_stamps_ns_[from];
    dropped[i] = line_dropped_[from];
    std::copy_n(line_values_.begin() + from * channel_count_, channel_count_, values.begin() + i * channel_count_);
    std::copy_n(line_deviations_.begin() + from * channel_count_, channel_count_,
                deviations.begin() + i * channel_count_);
  }
  line_stamps_ns_.swap(stamps);
  line_values_.swap(values);
  line_deviations_.swap(deviations);
  line_dropped_.swap(dropped);
  line_capacity_ = capacity;
  line_head_ = 0;
}

void ImpulseScreen::level_and_deviation(const double* values, double* deviations) {
  const std::size_t level_size = options_.level_sample_count;
  for (std::size_t c = 0; c < channel_count_; ++c) {
    ChannelState& channel = channels_[c];
    const double value = values[c];
    if (!is_usable_imu_value(value)) {  // NaN, Inf, beyond 1e100: left out like the engine does
      deviations[c] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    deviations[c] = channel.level_count > 0 ? value - channel.level_sum / static_cast<double>(channel.level_count)
                                            : std::numeric_limits<double>::quiet_NaN();
    if (channel.level_count == level_size) {
      channel.level_sum -= channel.level_ring[channel.level_next];
    } else {
      ++channel.level_count;
    }
    channel.level_ring[channel.level_next] = value;
    channel.level_sum += value;
    if (++channel.level_next == level_size) {
      // Once per turn the running sum is recomputed, so its rounding never accumulates.
      channel.level_next = 0;
      channel.level_sum = 0.0;
      for (const double kept : channel.level_ring) channel.level_sum += kept;
    }
  }
}

void ImpulseScreen::initialise_scales() {
  // Iterated from the plain mean square down to the clipped fixed point: spikes among the first
  // samples inflate only the starting value. The map's slope at the fixed point is
  // c^2 P(|z| > c) / kClippedMoment = 0.024 for Gaussian noise, so a few iterations converge.
  std::vector<double> squares;
  for (std::size_t c = 0; c < channel_count_; ++c) {
    squares.clear();
    for (std::size_t i = 0; i < line_size_; ++i) {
      const double deviation = line_deviations_[line_index(i) * channel_count_ + c];
      if (std::isfinite(deviation)) squares.push_back(deviation * deviation);
    }
    ChannelState& channel = channels_[c];
    channel.scale_sample_count = static_cast<std::int64_t>(squares.size());
    if (squares.empty()) continue;
    double mean_square = 0.0;
    for (const double square : squares) mean_square += square;
    mean_square /= static_cast<double>(squares.size());
    for (int iteration = 0; iteration < 200 && mean_square > 0.0; ++iteration) {
      const double clip = kScaleClipSigma * kScaleClipSigma * mean_square;
      double clipped = 0.0;
      for (const double square : squares) clipped += std::min(square, clip);
      const double next = clipped / static_cast<double>(squares.size()) / kClippedMoment;
      const bool converged = std::abs(next - mean_square) <= 1e-12 * mean_square;
      mean_square = next;
      if (converged) break;
    }
    channel.mean_square = mean_square;
  }
  scales_ready_ = true;
}

void ImpulseScreen::update_scale(std::size_t c, double deviation) {
  // Every screened deviation updates the scale, clipped: a knock adds at most
  // (c^2 - 1) / scale_memory_sample_count of the variance per sample (1.2e-4), while a lasting rise of the
  // noise (which is not an event once it lasts) is followed within some ten thousand samples.
  ChannelState& channel = channels_[c];
  const double square = deviation * deviation;
  const double term =
      (channel.mean_square > 0.0 ? std::min(square, kScaleClipSigma * kScaleClipSigma * channel.mean_square) : square) /
      kClippedMoment;
  ++channel.scale_sample_count;
  const double weight = channel.scale_sample_count < static_cast<std::int64_t>(options_.scale_memory_sample_count)
                            ? 1.0 / static_cast<double>(channel.scale_sample_count)
                            : scale_weight_floor_;
  channel.mean_square += weight * (term - channel.mean_square);
}

// The deviation in scales, or NaN where the channel is not screened (no value, no scale yet).
double ImpulseScreen::sigmas(std::size_t c, double deviation, double value) const {
  const double mean_square = channels_[c].mean_square;
  if (!std::isfinite(deviation) || mean_square <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  const double rounding = kRoundingFraction * value;
  return deviation / std::sqrt(std::max(mean_square, rounding * rounding));
}

void ImpulseScreen::process(std::size_t i) {
  const std::size_t index = line_index(i);
  const std::int64_t stamp_ns = line_stamps_ns_[index];
  const double* deviations = &line_deviations_[index * channel_count_];
  const double* values = &line_values_[index * channel_count_];
  bool flagged = false;
  for (std::size_t c = 0; c < channel_count_; ++c) {
    const double deviation = deviations[c];
    if (!std::isfinite(deviation)) continue;
    const double mean_square = channels_[c].mean_square;
    const double rounding = kRoundingFraction * values[c];
    if (mean_square > 0.0 && deviation * deviation > threshold_square_ * std::max(mean_square, rounding * rounding)) {
      flagged = true;
    }
  }
  if (flagged && !window_open_) open_window(i);
  if (window_open_ && !flagged && stamp_ns - window_.last_flag_stamp_ns > guard_after_ns_ &&
      window_.event.dropped_sample_count >= min_dropped_samples_) {
    close_window();
  }
  if (window_open_) {
    drop(i);
    if (flagged) {
      if (window_.event.flagged_sample_count == 0) window_.event.onset_stamp_ns = stamp_ns;
      window_.last_flag_stamp_ns = stamp_ns;
      ++window_.event.flagged_sample_count;
    }
  }
  // After the peaks: a flagged channel's peak is in the scale it was flagged against.
  for (std::size_t c = 0; c < channel_count_; ++c) {
    if (std::isfinite(deviations[c])) update_scale(c, deviations[c]);
  }
  latest_processed_stamp_ns_ = stamp_ns;
}

void ImpulseScreen::open_window(std::size_t i) {
  const std::int64_t stamp_ns = line_stamps_ns_[line_index(i)];
  // The guard before: the held samples at most guard_before_s older, back to a dropped one.
  std::size_t start = i;
  while (start > 0 && !line_dropped_[line_index(start - 1)] &&
         line_stamps_ns_[line_index(start - 1)] >= stamp_ns - guard_before_ns_) {
    --start;
  }
  // The samples after the last window are all still held when they span less than merge_gap_s
  // (release keeps guard_before_s + merge_gap_s).
  const bool near_last = window_.last_sequence + 1 >= front_sequence_ &&
                         window_.event.end_stamp_ns >= line_stamps_ns_[line_index(start)] - merge_gap_ns_;
  if (near_last) {
    // One event with the last one: reopen it and drop what lies between.
    if (window_.recorded) events_.pop_back();
    --counts_.event_count;
    start = static_cast<std::size_t>(window_.last_sequence + 1 - front_sequence_);
  } else {
    window_.event = ImpulseEvent();
    window_.event.start_stamp_ns = line_stamps_ns_[line_index(start)];
    std::fill(window_.peak_sigma.begin(), window_.peak_sigma.end(), 0.0);
    std::fill(window_.peak_stamp_ns.begin(), window_.peak_stamp_ns.end(), 0);
  }
  window_open_ = true;
  window_.last_flag_stamp_ns = stamp_ns;
  for (std::size_t j = start; j < i; ++j) drop(j);
}

void ImpulseScreen::drop(std::size_t i) {
  const std::size_t index = line_index(i);
  line_dropped_[index] = 1;
  ++dropped_count_;
  ++window_.event.dropped_sample_count;
  window_.event.end_stamp_ns = line_stamps_ns_[index];
  window_.last_sequence = front_sequence_ + static_cast<std::int64_t>(i);
  for (std::size_t c = 0; c < channel_count_; ++c) {
    const double z = sigmas(c, line_deviations_[index * channel_count_ + c], line_values_[index * channel_count_ + c]);
    if (std::abs(z) > std::abs(window_.peak_sigma[c])) {
      window_.peak_sigma[c] = z;
      window_.peak_stamp_ns[c] = line_stamps_ns_[index];
    }
  }
}

ImpulseEvent ImpulseScreen::window_event() const {
  ImpulseEvent event = window_.event;
  event.channels.clear();
  event.peak_sigma = 0.0;
  for (std::size_t c = 0; c < channel_count_; ++c) {
    const double peak = window_.peak_sigma[c];
    if (std::abs(peak) > options_.threshold_sigma) event.channels.push_back({c, peak, window_.peak_stamp_ns[c]});
    if (std::abs(peak) > std::abs(event.peak_sigma)) {
      event.peak_sigma = peak;
      event.peak_channel = c;
      event.peak_stamp_ns = window_.peak_stamp_ns[c];
    }
  }
  return event;
}

void ImpulseScreen::close_window() {
  window_.recorded = events_.size() < options_.max_recorded_events;
  if (window_.recorded) events_.push_back(window_event());
  ++counts_.event_count;
  window_open_ = false;
}

void ImpulseScreen::release(bool all, ScreenedSamples& passed) {
  while (processed_ > 0) {
    const std::size_t index = line_index(0);
    if (!line_dropped_[index]) {
      // A later detection reaches back guard_before_s from a later stamp, and merge_gap_s more
      // to a window before it: older samples are safe.
      const bool guarded = line_stamps_ns_[index] >= latest_processed_stamp_ns_ - guard_before_ns_ - merge_gap_ns_;
      if (!all && guarded && line_size_ <= kMaxDelayedSamples) break;
      passed.stamps_ns.push_back(line_stamps_ns_[index]);
      passed.values.insert(passed.values.end(), line_values_.begin() + index * channel_count_,
                           line_values_.begin() + (index + 1) * channel_count_);
      ++counts_.passed_sample_count;
    }
    line_head_ = (line_head_ + 1) & (line_capacity_ - 1);
    --line_size_;
    --processed_;
    ++front_sequence_;
  }
}

ImpulseScreenReport ImpulseScreen::report() const {
  // An event still open is reported as it stands (its window may still grow).
  auto report = screen_report<ImpulseScreenReport>(
      counts_, channels_, events_, window_open_, [this] { return window_event(); }, options_.max_recorded_events);
  report.dropped_sample_count = dropped_count_;
  return report;
}

}  // namespace allan
}  // namespace imu_lab
