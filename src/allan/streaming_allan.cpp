#include "imu_lab/allan/streaming_allan.h"

#include <cmath>
#include <string>

#include "imu_lab/allan/checkpoint.h"
#include "imu_lab/allan/checkpoint_codec.h"
#include "imu_lab/allan/noise_type.h"
#include "imu_lab/allan/streaming_points.h"
#include "imu_lab/allan/streaming_tau_plan.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/usable_imu_values.h"

namespace imu_lab {
namespace allan {
namespace {

void save_options(const StreamingOptions& options, BinaryWriter& out) {
  out.put_u64(options.channel_count);
  out.put_i64(static_cast<std::int64_t>(options.input_kind));
  out.put_i64(static_cast<std::int64_t>(options.tau_spacing));
  out.put_f64(options.points_per_decade);
  out.put_f64(options.max_tau_s);
  out.put_i64(options.exact_max_averaging_factor);
  out.put_u64(options.warm_up_sample_count);
  out.put_f64(options.gap_factor);
  out.put_i64(static_cast<std::int64_t>(options.stamp_policy));
  out.put_f64(options.confidence);
}

// Each channel's report alone takes this much of the payload (serialise()).
constexpr std::size_t kChannelReportBytes = 5 * sizeof(std::int64_t);

StreamingOptions load_options(BinaryReader& in) {
  StreamingOptions options;
  options.channel_count = in.get_u64();
  options.input_kind = in.get_enum(InputKind::kIncrement, "input_kind");
  options.tau_spacing = in.get_enum(TauSpacing::kEveryM, "tau_spacing");
  options.points_per_decade = in.get_f64();
  options.max_tau_s = in.get_f64();
  options.exact_max_averaging_factor = static_cast<int>(in.get_i64());
  options.warm_up_sample_count = in.get_u64();
  options.gap_factor = in.get_f64();
  options.stamp_policy = in.get_enum(StampPolicy::kStop, "stamp_policy");
  options.confidence = in.get_f64();
  // Refused before the engine allocates for that many channels.
  if (options.channel_count > in.remaining_bytes() / kChannelReportBytes) {
    in.fail("channel_count " + std::to_string(options.channel_count) + " is more than the payload holds");
  }
  try {
    options.validate();
  } catch (const ConfigError& error) {
    in.fail(std::string("options out of range: ") + error.what());
  }
  return options;
}

}  // namespace

StreamingAllan::StreamingAllan(const StreamingOptions& options) : options_(options), warm_up_(options.channel_count) {
  options_.validate();
  channel_reports_.resize(options_.channel_count);
}

std::size_t StreamingAllan::history_capacity() const {
  return static_cast<std::size_t>(kMinimumLag1Points) * options_.exact_max_averaging_factor + 1;
}

void StreamingAllan::push(std::int64_t stamp_ns, const std::vector<double>& values) {
  push(stamp_ns, values.data(), values.size());
}

void StreamingAllan::push(std::int64_t stamp_ns, const double* values, std::size_t value_count) {
  if (value_count != options_.channel_count) {
    throw InputError("StreamingAllan::push: sample " + std::to_string(input_sample_count_) + " has " +
                     std::to_string(value_count) + " values; the engine was configured for " +
                     std::to_string(options_.channel_count) + " channels");
  }
  take(stamp_ns, values);
}

void StreamingAllan::push_block(const std::int64_t* stamps_ns, const double* values_row_major,
                                std::size_t sample_count) {
  const std::size_t channel_count = options_.channel_count;
  for (std::size_t k = 0; k < sample_count; ++k) take(stamps_ns[k], values_row_major + k * channel_count);
}

void StreamingAllan::take(std::int64_t stamp_ns, const double* values) {
  const std::int64_t sample_index = input_sample_count_;
  if (warmed_up_) {
    accept(stamp_ns, values, sample_index);
  } else {
    warm_up_.add(stamp_ns, values);
    if (warm_up_.sample_count() >= options_.warm_up_sample_count) finish_warm_up();
  }
  ++input_sample_count_;
  last_stamp_ns_ = stamp_ns;
}

bool StreamingAllan::has_unprocessed_points() const {
  for (const ChannelAccumulator& channel : channels_) {
    if (channel.has_unprocessed_points()) return true;
  }
  return false;
}

void StreamingAllan::flush_channels() {
  for (ChannelAccumulator& channel : channels_) channel.flush();
}

void StreamingAllan::finish_warm_up() {
  const std::int64_t tau0_ns = warm_up_.median_interval_ns();
  if (tau0_ns <= 0) {
    throw InputError("StreamingAllan: the first " + std::to_string(warm_up_.sample_count()) +
                     " samples have no increasing stamps, so tau0 cannot be estimated; check the stamps");
  }
  const double tau0_s = static_cast<double>(tau0_ns) * 1e-9;
  const TauPlan plan = plan_taus(options_, tau0_s);
  const std::vector<double> offsets = warm_up_.finite_means();
  channels_.clear();
  channels_.reserve(options_.channel_count);
  for (std::size_t c = 0; c < options_.channel_count; ++c) {
    channels_.emplace_back(plan, offsets[c], history_capacity());
    channel_reports_[c].offset = offsets[c];
  }
  stamps_ = StampTracker(tau0_ns, options_.gap_factor, options_.stamp_policy);
  warmed_up_ = true;
  for (std::size_t sample = 0; sample < warm_up_.sample_count(); ++sample) {
    accept(warm_up_.stamp_ns(sample), warm_up_.values(sample), static_cast<std::int64_t>(sample));
  }
  warm_up_.release();
}

void StreamingAllan::accept(std::int64_t stamp_ns, const double* values, std::int64_t sample_index) {
  const StampVerdict verdict = stamps_.classify(stamp_ns, sample_index);
  if (verdict == StampVerdict::kDuplicate || verdict == StampVerdict::kOutOfOrder) return;
  if (verdict == StampVerdict::kGap) {
    for (ChannelAccumulator& channel : channels_) channel.break_segment();
  }
  for (std::size_t c = 0; c < channels_.size(); ++c) {
    ChannelReport& report = channel_reports_[c];
    if (is_usable_imu_value(values[c])) {
      channels_[c].push(values[c]);
      ++report.finite_sample_count;
      continue;
    }
    // Excluded, and the channel's phase must not bridge the missing value.
    channels_[c].break_segment();
    if (report.non_finite_count == 0) report.first_non_finite_sample_index = sample_index;
    report.last_non_finite_sample_index = sample_index;
    ++report.non_finite_count;
  }
}

StreamingSnapshot StreamingAllan::snapshot() const {
  if (!warmed_up_) {
    // Fix tau0 on a copy from what has arrived so far, if it can be.
    if (warm_up_.median_interval_ns() > 0) {
      StreamingAllan provisional = *this;
      provisional.finish_warm_up();
      return provisional.snapshot();
    }
    StreamingSnapshot empty;
    empty.timing.input_sample_count = input_sample_count_;
    empty.channels = channel_reports_;
    return empty;
  }
  if (has_unprocessed_points()) {
    // Bring the statistics up to date on a copy: processing here would move the block
    // boundaries, and results must not depend on when (or whether) snapshots were taken.
    StreamingAllan processed = *this;
    processed.flush_channels();
    return processed.snapshot();
  }
  StreamingSnapshot result;
  result.warmed_up = true;
  stamps_.fill(result.timing);
  result.timing.input_sample_count = input_sample_count_;
  result.channels = channel_reports_;
  PointUnits units;
  units.tau0_s = result.timing.tau0_s;
  units.value_scale = options_.input_kind == InputKind::kIncrement ? 1.0 / units.tau0_s : 1.0;
  units.confidence = options_.confidence;
  result.curves.resize(kStreamingStatistics.size());
  for (const Statistic statistic : kStreamingStatistics) {
    auto& per_channel = result.curves[static_cast<std::size_t>(statistic)];
    for (const ChannelAccumulator& channel : channels_)
      per_channel.push_back(streaming_points(statistic, channel, units));
  }
  for (std::size_t c = 0; c < channels_.size(); ++c) {
    std::int64_t segments = 0;
    for (const auto& entry : channels_[c].levels().front().segment_phase_counts()) segments += entry.second;
    result.channels[c].segment_count = segments;
  }
  return result;
}

std::size_t StreamingAllan::state_size_bytes() const {
  std::size_t bytes = sizeof(*this) + warm_up_.heap_bytes() + channels_.capacity() * sizeof(ChannelAccumulator) +
                      channel_reports_.capacity() * sizeof(ChannelReport) +
                      kMaxRecordedStampEvents * sizeof(StampEvent);
  for (const ChannelAccumulator& channel : channels_) bytes += channel.heap_bytes();
  return bytes;
}

std::string StreamingAllan::serialise() const {
  BinaryWriter out;
  save_options(options_, out);
  out.put_i64(warmed_up_ ? 1 : 0);
  out.put_i64(input_sample_count_);
  out.put_i64(last_stamp_ns_);
  warm_up_.save(out);
  for (const ChannelReport& report : channel_reports_) {
    out.put_f64(report.offset);
    out.put_i64(report.finite_sample_count);
    out.put_i64(report.non_finite_count);
    out.put_i64(report.first_non_finite_sample_index);
    out.put_i64(report.last_non_finite_sample_index);
  }
  if (warmed_up_) {
    out.put_i64(stamps_.tau0_ns());
    stamps_.save(out);
    for (const ChannelAccumulator& channel : channels_) channel.save(out);
  }
  return out.bytes();
}

void StreamingAllan::deserialise_state(BinaryReader& in) {
  warmed_up_ = in.get_i64() != 0;
  input_sample_count_ = in.get_count();
  last_stamp_ns_ = in.get_i64();
  warm_up_.load(in);
  for (ChannelReport& report : channel_reports_) {
    report.offset = in.get_finite_f64();
    report.finite_sample_count = in.get_count();
    report.non_finite_count = in.get_count();
    report.first_non_finite_sample_index = in.get_i64();
    report.last_non_finite_sample_index = in.get_i64();
  }
  if (warmed_up_) {
    const std::int64_t tau0_ns = in.get_i64();
    if (tau0_ns <= 0) in.fail("non-positive tau0");
    // The plan is a pure function of the options and tau0, so rebuilding it gives the same shape.
    const TauPlan plan = plan_taus(options_, static_cast<double>(tau0_ns) * 1e-9);
    stamps_.load(in);
    if (stamps_.tau0_ns() != tau0_ns) in.fail("stamp tracker of another tau0");
    channels_.clear();
    for (std::size_t c = 0; c < options_.channel_count; ++c) {
      channels_.emplace_back(plan, 0.0, history_capacity());
      channels_.back().load(in);
    }
  }
  if (!in.at_end()) in.fail("unread bytes after the state");
}

void StreamingAllan::save_checkpoint(const std::string& path) const { write_checkpoint_file(path, serialise()); }

StreamingAllan StreamingAllan::load_checkpoint(const std::string& path) {
  const std::string payload = read_checkpoint_file(path);
  BinaryReader in(payload, "checkpoint " + path);
  StreamingAllan engine(load_options(in));
  engine.deserialise_state(in);
  return engine;
}

}  // namespace allan
}  // namespace imu_lab
