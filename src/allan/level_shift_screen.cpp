#include "imu_lab/allan/level_shift_screen.h"

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

const double kClippedMoment = clipped_gaussian_second_moment(kLevelShiftClipSigma);

// The sample interval is the median of this many first positive intervals.
constexpr std::size_t kIntervalCount = 33;

}  // namespace

void LevelShiftScreenOptions::validate() const {
  const std::string source = "LevelShiftScreenOptions";
  require_option(channel_count >= 1, source, "channel_count", "must be at least 1");
  require_option(std::isfinite(window_s) && window_s > 0.0 && window_s <= 3600.0, source, "window_s",
                 "must lie above 0 and at most 3600 s");
  require_option(std::isfinite(threshold_sigma) && threshold_sigma > kLevelShiftClipSigma, source, "threshold_sigma",
                 "must be a number above " + std::to_string(kLevelShiftClipSigma) +
                     " (scales of the difference; 10 is the default)");
  require_option(std::isfinite(guard_s) && guard_s >= 0.0 && guard_s <= 60.0, source, "guard_s",
                 "must lie between 0 and 60 s");
  require_option(std::isfinite(scale_warm_up_s) && scale_warm_up_s >= window_s, source, "scale_warm_up_s",
                 "must be at least window_s");
  require_option(std::isfinite(scale_memory_s) && scale_memory_s >= scale_warm_up_s, source, "scale_memory_s",
                 "must be at least scale_warm_up_s");
  require_option(std::isfinite(gap_factor) && gap_factor > 1.0 && gap_factor <= 1e6, source, "gap_factor",
                 "must be above 1 (the engine's, 1.5 is usual)");
  require_option(channel_group_size >= 1 && (channel_count + channel_group_size - 1) / channel_group_size <= 32, source,
                 "channel_group_size", "must be at least 1 and leave at most 32 groups");
}

LevelShiftScreen::LevelShiftScreen(const LevelShiftScreenOptions& options)
    : options_(options), counts_(options.enabled, options.threshold_sigma) {
  options_.validate();
  channel_count_ = options_.channel_count;
  window_ns_ = stamp_ns_from_seconds(options_.window_s);
  guard_ns_ = stamp_ns_from_seconds(options_.guard_s);
  channels_.resize(channel_count_);
  channel_masked_counts_.assign(channel_count_, 0);
  scratch_differences_.resize(channel_count_);
}

void LevelShiftScreen::push(const ScreenedSamples& input, ScreenedSamples& passed) {
  for (std::size_t i = 0; i < input.size(); ++i) push(input.stamps_ns[i], &input.values[i * channel_count_], passed);
}

void LevelShiftScreen::push(std::int64_t stamp_ns, const double* values, ScreenedSamples& passed) {
  if (passed_unscreened(options_.enabled, stamp_ns, values, channel_count_, counts_, passed)) return;
  if (!segment_empty_ && segment_boundary(stamp_ns)) end_segment(passed);
  last_stamp_ns_ = stamp_ns;
  if (segment_empty_) {
    segment_start_ns_ = stamp_ns;
    segment_empty_ = false;
  }
  // The centres whose window after them this sample completes (the window excludes it).
  while (centre_ < end_sequence() && stamp_ns - stamp_at(centre_) >= window_ns_) {
    evaluate_centre();
    advance_centre();
  }
  stamps_ns_.push_back(stamp_ns);
  masks_.push_back(0);
  for (std::size_t c = 0; c < channel_count_; ++c) {
    values_.push_back(values[c]);
    if (!is_usable_imu_value(values[c])) continue;
    channels_[c].after_sum += values[c];
    ++channels_[c].after_count;
  }
  release(false, passed);
}

void LevelShiftScreen::finish(ScreenedSamples& passed) {
  if (options_.enabled) end_segment(passed);
}

bool LevelShiftScreen::segment_boundary(std::int64_t stamp_ns) {
  const std::int64_t interval = stamp_ns - last_stamp_ns_;
  if (interval <= 0) return true;
  if (interval_ns_ == 0) {
    first_intervals_ns_.push_back(interval);
    if (first_intervals_ns_.size() == kIntervalCount) {
      std::vector<std::int64_t> sorted = first_intervals_ns_;
      std::nth_element(sorted.begin(), sorted.begin() + kIntervalCount / 2, sorted.end());
      interval_ns_ = sorted[kIntervalCount / 2];
    }
    return false;
  }
  return static_cast<double>(interval) > options_.gap_factor * static_cast<double>(interval_ns_);
}

void LevelShiftScreen::evaluate_centre() {
  const std::int64_t stamp_ns = stamp_at(centre_);
  // Only with a whole window before the centre inside the segment.
  if (stamp_ns - segment_start_ns_ < window_ns_) return;
  const bool screening = scaled_ns_ >= stamp_ns_from_seconds(options_.scale_warm_up_s);
  const std::int64_t step_ns = scaled_in_segment_ ? stamp_ns - last_scaled_stamp_ns_ : 0;
  last_scaled_stamp_ns_ = stamp_ns;
  scaled_in_segment_ = true;
  scaled_ns_ += step_ns;
  std::uint32_t flagged_groups = 0;
  std::vector<double>& differences = scratch_differences_;
  std::fill(differences.begin(), differences.end(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < channel_count_; ++c) {
    const ChannelState& channel = channels_[c];
    if (channel.before_count == 0 || channel.after_count == 0) continue;
    differences[c] = channel.after_sum / static_cast<double>(channel.after_count) -
                     channel.before_sum / static_cast<double>(channel.before_count);
    if (screening && channel.mean_square > 0.0 &&
        differences[c] * differences[c] > options_.threshold_sigma * options_.threshold_sigma * channel.mean_square) {
      flagged_groups |= std::uint32_t{1} << (c / options_.channel_group_size);
    }
  }
  const bool flagged = flagged_groups != 0;
  if (flagged) {
    const bool opening = !event_open_;
    event_groups_ = (opening ? 0 : event_groups_) | flagged_groups;
    if (opening) open_event(centre_);
    last_flag_stamp_ns_ = stamp_ns;
    for (std::size_t c = 0; c < channel_count_; ++c) {
      ChannelState& channel = channels_[c];
      if (!std::isfinite(differences[c]) || channel.mean_square <= 0.0) continue;
      const double sigmas = differences[c] / std::sqrt(channel.mean_square);
      if (std::abs(sigmas) > std::abs(channel.peak_sigma)) {
        channel.peak_sigma = sigmas;
        channel.peak_shift = differences[c];
        channel.peak_stamp_ns = stamp_ns;
      }
    }
  }
  if (event_open_) {
    if (flagged || stamp_ns - last_flag_stamp_ns_ <= guard_ns_) {
      mask(centre_);
    } else {
      close_event();
    }
  }
  // After the flag: a step is judged against the scale before it.
  for (std::size_t c = 0; c < channel_count_; ++c) {
    if (std::isfinite(differences[c])) update_scale(c, differences[c], step_ns);
  }
}

void LevelShiftScreen::update_scale(std::size_t c, double difference, std::int64_t step_ns) {
  // Clipped once a scale exists. At first a running mean (so the first scale is the plain one of
  // the first differences), then forgetting: the weight is the time the centre moved on over the
  // memory.
  ChannelState& channel = channels_[c];
  const double square = difference * difference;
  const double clip = kLevelShiftClipSigma * kLevelShiftClipSigma * channel.mean_square;
  const double term = channel.mean_square > 0.0 ? std::min(square, clip) / kClippedMoment : square;
  ++channel.scale_count;
  const double weight = std::max(1.0 / static_cast<double>(channel.scale_count),
                                 static_cast<double>(step_ns) * 1e-9 / options_.scale_memory_s);
  channel.mean_square += std::min(1.0, weight) * (term - channel.mean_square);
}

void LevelShiftScreen::advance_centre() {
  for (std::size_t c = 0; c < channel_count_; ++c) {
    const double value = value_at(centre_, c);
    if (!is_usable_imu_value(value)) continue;
    channels_[c].after_sum -= value;
    --channels_[c].after_count;
    channels_[c].before_sum += value;
    ++channels_[c].before_count;
  }
  ++centre_;
  if (centre_ == end_sequence()) return;
  const std::int64_t earliest_ns = stamp_at(centre_) - window_ns_;
  while (before_begin_ < centre_ && stamp_at(before_begin_) < earliest_ns) {
    for (std::size_t c = 0; c < channel_count_; ++c) {
      const double leaving = value_at(before_begin_, c);
      if (!is_usable_imu_value(leaving)) continue;
      channels_[c].before_sum -= leaving;
      --channels_[c].before_count;
    }
    ++before_begin_;
  }
}

void LevelShiftScreen::open_event(std::int64_t sequence) {
  event_ = LevelShiftEvent();
  for (ChannelState& channel : channels_) {
    channel.peak_sigma = channel.peak_shift = 0.0;
    channel.peak_stamp_ns = 0;
  }
  event_open_ = true;
  // The guard before: held samples at most guard_s older (none has passed yet: release lags the
  // centre by guard_s).
  const std::int64_t earliest_ns = stamp_at(sequence) - guard_ns_;
  std::int64_t start = sequence;
  while (start > release_ && stamp_at(start - 1) >= earliest_ns) --start;
  event_.start_stamp_ns = stamp_at(start);
  for (std::int64_t i = start; i < sequence; ++i) mask(i);
}

void LevelShiftScreen::mask(std::int64_t sequence) {
  std::uint32_t& groups = masks_[offset(sequence)];
  if (groups == 0) ++event_.masked_sample_count;
  groups |= event_groups_;
  event_.end_stamp_ns = stamp_at(sequence);
}

LevelShiftEvent LevelShiftScreen::event_as_it_stands() const {
  LevelShiftEvent event = event_;
  event.channels.clear();
  for (std::size_t c = 0; c < channel_count_; ++c) {
    const ChannelState& channel = channels_[c];
    if (std::abs(channel.peak_sigma) > options_.threshold_sigma) {
      event.channels.push_back({c, channel.peak_shift, channel.peak_sigma, channel.peak_stamp_ns});
    }
    if (std::abs(channel.peak_sigma) > std::abs(event.peak_sigma)) {
      event.peak_sigma = channel.peak_sigma;
      event.peak_channel = c;
      event.step_stamp_ns = channel.peak_stamp_ns;
    }
    if (event_groups_ & (std::uint32_t{1} << (c / options_.channel_group_size))) event.masked_channels.push_back(c);
  }
  return event;
}

void LevelShiftScreen::close_event() {
  if (events_.size() < options_.max_recorded_events) events_.push_back(event_as_it_stands());
  ++counts_.event_count;
  event_open_ = false;
}

void LevelShiftScreen::release(bool all, ScreenedSamples& passed) {
  const std::int64_t safe_before_ns =
      centre_ < end_sequence() ? stamp_at(centre_) - guard_ns_ : std::numeric_limits<std::int64_t>::max();
  // At the end the samples no centre reached yet pass too (none of them is masked).
  const std::int64_t last = all ? end_sequence() : centre_;
  while (release_ < last && (all || stamp_at(release_) < safe_before_ns)) {
    const std::uint32_t groups = masks_[offset(release_)];
    passed.stamps_ns.push_back(stamp_at(release_));
    for (std::size_t c = 0; c < channel_count_; ++c) {
      const bool masked = groups & (std::uint32_t{1} << (c / options_.channel_group_size));
      passed.values.push_back(masked ? std::numeric_limits<double>::quiet_NaN() : value_at(release_, c));
      channel_masked_counts_[c] += masked;
    }
    masked_count_ += groups != 0;
    ++counts_.passed_sample_count;
    ++release_;
  }
  const std::int64_t keep_from = std::min(before_begin_, release_);
  while (front_sequence_ < keep_from) {
    stamps_ns_.pop_front();
    masks_.pop_front();
    values_.erase(values_.begin(), values_.begin() + static_cast<std::ptrdiff_t>(channel_count_));
    ++front_sequence_;
  }
}

void LevelShiftScreen::end_segment(ScreenedSamples& passed) {
  if (event_open_) close_event();
  release(true, passed);
  stamps_ns_.clear();
  values_.clear();
  masks_.clear();
  front_sequence_ = before_begin_ = centre_ = release_;
  for (ChannelState& channel : channels_) {
    channel.before_sum = channel.after_sum = 0.0;
    channel.before_count = channel.after_count = 0;
  }
  segment_empty_ = true;
  scaled_in_segment_ = false;
}

LevelShiftReport LevelShiftScreen::report() const {
  auto report = screen_report<LevelShiftReport>(
      counts_, channels_, events_, event_open_, [this] { return event_as_it_stands(); }, options_.max_recorded_events);
  report.window_s = options_.window_s;
  report.masked_sample_count = masked_count_;
  report.channel_masked_counts = channel_masked_counts_;
  return report;
}

}  // namespace allan
}  // namespace imu_lab
