#include "imu_lab/pipeline/allan_summary.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace pipeline {
namespace {

// The summary lists this many irregular stamps; the counts cover all of them.
constexpr std::size_t kListedStampEvents = 20;

const char* event_name(allan::StampEventKind kind) {
  switch (kind) {
    case allan::StampEventKind::kGap: return "gap";
    case allan::StampEventKind::kDuplicate: return "duplicate";
    case allan::StampEventKind::kOutOfOrder: return "out_of_order";
  }
  return "unknown";
}

void emit_irregularity(YAML::Emitter& out, const char* key, std::int64_t count, const std::string& action) {
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "count" << YAML::Value << count;
  out << YAML::Key << "action" << YAML::Value << (count == 0 ? std::string("none needed") : action);
  out << YAML::EndMap;
}

void emit_timing(YAML::Emitter& out, const AllanRunDescription& run, const allan::TimingReport& timing) {
  const bool stop_policy = run.engine.stamp_policy == allan::StampPolicy::kStop;
  out << YAML::Key << "tau0_s" << YAML::Value << timing.tau0_s;
  out << YAML::Key << "sample_rate_hz" << YAML::Value << (timing.tau0_s > 0.0 ? 1.0 / timing.tau0_s : 0.0);
  out << YAML::Key << "interval_rms_deviation_s" << YAML::Value << timing.interval_rms_deviation_s;
  out << YAML::Key << "interval_max_deviation_s" << YAML::Value << timing.interval_max_deviation_s;
  out << YAML::Key << "stamp_policy" << YAML::Value << (stop_policy ? "stop" : "split_and_pool");
  emit_irregularity(out, "gaps", timing.gap_count, "run split at each gap, the segments' sums pooled");
  out << YAML::Key << "gap_time_s" << YAML::Value << timing.gap_time_s;
  // Of those, the holes the impulse screen left where it took a knock out: not the input's.
  const ScreenMadeGaps screen_gaps = impulse_screen_gaps(timing, run.impulses, run.engine.gap_factor);
  out << YAML::Key << "gaps_made_by_impulse_screen" << YAML::Value << screen_gaps.count;
  emit_irregularity(out, "duplicates", timing.duplicate_count, "samples dropped");
  emit_irregularity(out, "out_of_order", timing.out_of_order_count, "samples dropped");
  out << YAML::Key << "first_stamp_events" << YAML::Value << YAML::BeginSeq;
  for (std::size_t i = 0; i < std::min(timing.events.size(), kListedStampEvents); ++i) {
    const allan::StampEvent& event = timing.events[i];
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "kind" << YAML::Value << event_name(event.kind) << YAML::Key
        << "sample_index" << YAML::Value << event.sample_index << YAML::Key << "stamp_ns" << YAML::Value
        << event.stamp_ns << YAML::Key << "previous_stamp_ns" << YAML::Value << event.previous_stamp_ns << YAML::EndMap;
  }
  out << YAML::EndSeq;
}

void emit_channels(YAML::Emitter& out, const AllanRunDescription& run, const allan::StreamingSnapshot& snapshot) {
  // An increment's offset is per sample; the summary gives it as a rate like the curves.
  const double offset_scale =
      run.input == AllanInput::kIncrement && snapshot.timing.tau0_s > 0.0 ? 1.0 / snapshot.timing.tau0_s : 1.0;
  std::int64_t non_finite_total = 0;
  out << YAML::Key << "channels" << YAML::Value << YAML::BeginMap;
  for (std::size_t c = 0; c < snapshot.channels.size() && c < kAllanChannelCount; ++c) {
    const allan::ChannelReport& report = snapshot.channels[c];
    const std::string unit = kAllanChannelUnits[c];
    // The values the level-shift screen set to NaN are its own, not the input's.
    const std::int64_t masked =
        c < run.level_shifts.channel_masked_counts.size() ? run.level_shifts.channel_masked_counts[c] : 0;
    non_finite_total += report.non_finite_count - masked;
    out << YAML::Key << kAllanChannelNames[c] << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "offset_" + unit << YAML::Value << report.offset * offset_scale;
    out << YAML::Key << "finite_samples" << YAML::Value << report.finite_sample_count;
    out << YAML::Key << "non_finite_samples" << YAML::Value << report.non_finite_count - masked;
    if (masked > 0) out << YAML::Key << "level_shift_masked_samples" << YAML::Value << masked;
    out << YAML::Key << "segments" << YAML::Value << report.segment_count;
    if (c < run.output_steps.size()) {
      // The output's LSB (0: not quantised), in the unit of the values read.
      out << YAML::Key << std::string("output_step_") + allan_value_unit(run.input, c) << YAML::Value
          << run.output_steps[c].step;
    }
    const allan::StabilityPoint* minimum = minimum_point(snapshot.curve(allan::Statistic::kOverlappingAllan, c));
    if (minimum != nullptr) {
      out << YAML::Key << "min_oadev_" + unit << YAML::Value << minimum->deviation;
      out << YAML::Key << "min_oadev_tau_s" << YAML::Value << minimum->tau_s;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  emit_irregularity(out, "non_finite_values", non_finite_total,
                    "values excluded; each splits its channel's run, the segments' sums pooled");
}

void emit_impulse_event(YAML::Emitter& out, const allan::ImpulseEvent& event, std::int64_t first_stamp_ns) {
  const auto from_start_s = [&](std::int64_t stamp_ns) { return seconds_between(first_stamp_ns, stamp_ns); };
  out << YAML::BeginMap;
  out << YAML::Key << "onset_from_start_s" << YAML::Value << from_start_s(event.onset_stamp_ns);
  out << YAML::Key << "window_from_start_s" << YAML::Value << YAML::Flow << YAML::BeginSeq
      << from_start_s(event.start_stamp_ns) << from_start_s(event.end_stamp_ns) << YAML::EndSeq;
  out << YAML::Key << "peak_from_start_s" << YAML::Value << from_start_s(event.peak_stamp_ns);
  out << YAML::Key << "onset_stamp_ns" << YAML::Value << event.onset_stamp_ns;
  out << YAML::Key << "window_stamps_ns" << YAML::Value << YAML::Flow << YAML::BeginSeq << event.start_stamp_ns
      << event.end_stamp_ns << YAML::EndSeq;
  out << YAML::Key << "peak_stamp_ns" << YAML::Value << event.peak_stamp_ns;
  out << YAML::Key << "peak_channel" << YAML::Value << kAllanChannelNames.at(event.peak_channel);
  out << YAML::Key << "peak_sigma" << YAML::Value << event.peak_sigma;
  out << YAML::Key << "channel_peaks_sigma" << YAML::Value << YAML::Flow << YAML::BeginMap;
  for (const allan::ImpulseChannelPeak& peak : event.channels) {
    out << YAML::Key << kAllanChannelNames.at(peak.channel) << YAML::Value << peak.peak_sigma;
  }
  out << YAML::EndMap;
  out << YAML::Key << "flagged_samples" << YAML::Value << event.flagged_sample_count;
  out << YAML::Key << "dropped_samples" << YAML::Value << event.dropped_sample_count;
  out << YAML::EndMap;
}

void emit_level_shift(YAML::Emitter& out, AllanInput input, const allan::LevelShiftEvent& shift,
                      std::int64_t first_stamp_ns) {
  const auto from_start_s = [&](std::int64_t stamp_ns) { return seconds_between(first_stamp_ns, stamp_ns); };
  out << YAML::BeginMap;
  out << YAML::Key << "step_from_start_s" << YAML::Value << from_start_s(shift.step_stamp_ns);
  out << YAML::Key << "window_from_start_s" << YAML::Value << YAML::Flow << YAML::BeginSeq
      << from_start_s(shift.start_stamp_ns) << from_start_s(shift.end_stamp_ns) << YAML::EndSeq;
  out << YAML::Key << "step_stamp_ns" << YAML::Value << shift.step_stamp_ns;
  out << YAML::Key << "window_stamps_ns" << YAML::Value << YAML::Flow << YAML::BeginSeq << shift.start_stamp_ns
      << shift.end_stamp_ns << YAML::EndSeq;
  out << YAML::Key << "peak_channel" << YAML::Value << kAllanChannelNames.at(shift.peak_channel);
  out << YAML::Key << "peak_sigma" << YAML::Value << shift.peak_sigma;
  out << YAML::Key << "shifts" << YAML::Value << YAML::Flow << YAML::BeginMap;
  for (const allan::LevelShiftChannel& channel : shift.channels) {
    out << YAML::Key
        << std::string(kAllanChannelNames.at(channel.channel)) + "_" + allan_value_unit(input, channel.channel)
        << YAML::Value << channel.shift;
  }
  out << YAML::EndMap;
  out << YAML::Key << "masked_channels" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (std::size_t c : shift.masked_channels) out << kAllanChannelNames.at(c);
  out << YAML::EndSeq;
  out << YAML::Key << "masked_samples" << YAML::Value << shift.masked_sample_count;
  out << YAML::EndMap;
}

void emit_level_shifts(YAML::Emitter& out, const AllanRunDescription& run) {
  const allan::LevelShiftReport& screen = run.level_shifts;
  out << YAML::Key << "level_shift_screen" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "enabled" << YAML::Value << screen.enabled;
  if (screen.enabled) {
    out << YAML::Key << "threshold_sigma" << YAML::Value << screen.threshold_sigma;
    out << YAML::Key << "window_s" << YAML::Value << screen.window_s;
    out << YAML::Key << "masked_samples" << YAML::Value << screen.masked_sample_count;
    emit_irregularity(out, "shifts", screen.event_count,
                      "the stepping triad's values around each step set to NaN: its channels' runs split there, "
                      "the segments' sums pooled (counted here, not under non_finite_values)");
    out << YAML::Key << "difference_scales" << YAML::Value << YAML::BeginMap;
    for (std::size_t c = 0; c < screen.channel_scales.size() && c < kAllanChannelCount; ++c) {
      out << YAML::Key << std::string(kAllanChannelNames[c]) + "_" + allan_value_unit(run.input, c) << YAML::Value
          << screen.channel_scales[c];
    }
    out << YAML::EndMap;
    out << YAML::Key << "listed_shifts" << YAML::Value << YAML::BeginSeq;
    for (const allan::LevelShiftEvent& shift : screen.events) {
      emit_level_shift(out, run.input, shift, screen.first_stamp_ns);
    }
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
}

void emit_impulses(YAML::Emitter& out, const AllanRunDescription& run) {
  const allan::ImpulseScreenReport& screen = run.impulses;
  out << YAML::Key << "impulse_screen" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "enabled" << YAML::Value << screen.enabled;
  if (screen.enabled) {
    out << YAML::Key << "threshold_sigma" << YAML::Value << screen.threshold_sigma;
    out << YAML::Key << "input_samples" << YAML::Value << screen.input_sample_count;
    out << YAML::Key << "dropped_samples" << YAML::Value << screen.dropped_sample_count;
    emit_irregularity(out, "events", screen.event_count,
                      "the samples of each event window dropped: the run split there, the segments' sums pooled");
    out << YAML::Key << "deviation_scales" << YAML::Value << YAML::BeginMap;
    for (std::size_t c = 0; c < screen.channel_scales.size() && c < kAllanChannelCount; ++c) {
      out << YAML::Key << std::string(kAllanChannelNames[c]) + "_" + allan_value_unit(run.input, c) << YAML::Value
          << screen.channel_scales[c];
    }
    out << YAML::EndMap;
    out << YAML::Key << "listed_events" << YAML::Value << YAML::BeginSeq;
    for (const allan::ImpulseEvent& event : screen.events) emit_impulse_event(out, event, screen.first_stamp_ns);
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
}

// The files of a split recording in the order read, and the gap at each join (the engine treats
// it like any gap in the stamps: the timing section counts it).
void emit_split_files(YAML::Emitter& out, const AllanRunDescription& run) {
  out << YAML::Key << "files" << YAML::Value << YAML::BeginSeq;
  for (const std::string& file : run.files) out << file;
  out << YAML::EndSeq;
  out << YAML::Key << "file_joins" << YAML::Value << YAML::BeginSeq;
  for (const io::FileJoin& join : run.joins) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "before" << YAML::Value << join.before_path << YAML::Key
        << "after" << YAML::Value << join.after_path << YAML::Key << "gap_s" << YAML::Value << join.gap_s
        << YAML::EndMap;
  }
  out << YAML::EndSeq;
}

}  // namespace

ScreenMadeGaps impulse_screen_gaps(const allan::TimingReport& timing, const allan::ImpulseScreenReport& screen,
                                   double gap_factor) {
  ScreenMadeGaps made;
  const double largest_regular_ns = gap_factor * timing.tau0_s * 1e9;
  for (const allan::StampEvent& gap : timing.events) {
    if (gap.kind != allan::StampEventKind::kGap) continue;
    // The holes between the samples the input had there: from the last accepted stamp to each
    // dropped window, between windows, and from the last window to the gap's stamp.
    std::int64_t hole_start_ns = gap.previous_stamp_ns;
    std::int64_t largest_hole_ns = 0;
    bool holds_a_window = false;
    for (const allan::ImpulseEvent& window : screen.events) {
      if (window.start_stamp_ns <= gap.previous_stamp_ns || window.end_stamp_ns >= gap.stamp_ns) continue;
      holds_a_window = true;
      largest_hole_ns = std::max(largest_hole_ns, window.start_stamp_ns - hole_start_ns);
      hole_start_ns = window.end_stamp_ns;
    }
    largest_hole_ns = std::max(largest_hole_ns, gap.stamp_ns - hole_start_ns);
    if (holds_a_window && static_cast<double>(largest_hole_ns) <= largest_regular_ns) {
      ++made.count;
      made.time_s += seconds_between(gap.previous_stamp_ns, gap.stamp_ns) - timing.tau0_s;
    }
  }
  return made;
}

const allan::StabilityPoint* minimum_point(const std::vector<allan::StabilityPoint>& curve) {
  const auto smallest = std::min_element(curve.begin(), curve.end(),
                                         [](const auto& a, const auto& b) { return a.deviation < b.deviation; });
  return smallest == curve.end() ? nullptr : &*smallest;
}

std::string format_allan_summary(const AllanRunDescription& run, const allan::StreamingSnapshot& snapshot) {
  YAML::Emitter out;
  out.SetDoublePrecision(15);  // tau0 0.005, not 0.0050000000000000001
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << "imu_lab_allan_summary";
  if (!run.bag.empty()) out << YAML::Key << "bag" << YAML::Value << run.bag;
  if (run.files.size() > 1) emit_split_files(out, run);
  if (!run.bag.empty()) {
    out << YAML::Key << "time_window" << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "description" << YAML::Value << describe_time_window(run.window);
    out << YAML::Key << "start_s" << YAML::Value << run.window.start_s;
    if (std::isfinite(run.window.end_s)) out << YAML::Key << "end_s" << YAML::Value << run.window.end_s;
    out << YAML::EndMap;
  }
  out << YAML::Key << "topic" << YAML::Value << run.topic;
  out << YAML::Key << "input" << YAML::Value << allan_input_name(run.input);
  out << YAML::Key << "message_type" << YAML::Value << allan_input_datatype(run.input);
  out << YAML::Key << "samples" << YAML::Value << snapshot.timing.input_sample_count;
  out << YAML::Key << "accepted_samples" << YAML::Value << snapshot.timing.accepted_sample_count;
  if (run.skipped_before_checkpoint > 0) {
    out << YAML::Key << "skipped_before_checkpoint" << YAML::Value << run.skipped_before_checkpoint;
  }
  emit_timing(out, run, snapshot.timing);
  emit_impulses(out, run);
  emit_level_shifts(out, run);
  emit_channels(out, run, snapshot);
  if (run.warm_up) {
    out << YAML::Key << "warm_up_removed" << YAML::Value
        << "the fitted transients, before the statistics (warm_up.yaml)";
  }
  out << YAML::Key << "confidence" << YAML::Value << run.engine.confidence;
  out << YAML::Key << "points_per_decade" << YAML::Value << run.engine.points_per_decade;
  out << YAML::Key << "max_tau_s" << YAML::Value << run.engine.max_tau_s;
  out << YAML::Key << "exact_max_averaging_factor" << YAML::Value << run.engine.exact_max_averaging_factor;
  out << YAML::Key << "gap_factor" << YAML::Value << run.engine.gap_factor;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace pipeline
}  // namespace imu_lab

namespace imu_lab {
namespace pipeline {

std::string format_impulse_events(const std::string& prefix, const allan::ImpulseScreenReport& screen) {
  if (!screen.enabled) return prefix + "impulse screen off: knocks and spikes, if any, are in the curves\n";
  char line[512];
  std::snprintf(
      line, sizeof line, "impulse screen (threshold %.3g scales): %lld events, %lld samples left out of the curves%s\n",
      screen.threshold_sigma, static_cast<long long>(screen.event_count),
      static_cast<long long>(screen.dropped_sample_count), screen.event_count > 0 ? "; the run is split at each" : "");
  std::string text = prefix + line;
  const auto from_start_s = [&](std::int64_t stamp_ns) { return seconds_between(screen.first_stamp_ns, stamp_ns); };
  for (std::size_t i = 0; i < screen.events.size(); ++i) {
    const allan::ImpulseEvent& event = screen.events[i];
    std::snprintf(line, sizeof line,
                  "  event %zu: onset %.2f s from the start (stamp %.9f s), dropped %.2f-%.2f s, peak %.1f scales in "
                  "%s at %.2f s; over the threshold:",
                  i + 1, from_start_s(event.onset_stamp_ns), seconds_from_stamp_ns(event.onset_stamp_ns),
                  from_start_s(event.start_stamp_ns), from_start_s(event.end_stamp_ns), event.peak_sigma,
                  kAllanChannelNames.at(event.peak_channel), from_start_s(event.peak_stamp_ns));
    text += prefix + line;
    for (const allan::ImpulseChannelPeak& peak : event.channels) {
      std::snprintf(line, sizeof line, " %s %.1f", kAllanChannelNames.at(peak.channel), peak.peak_sigma);
      text += line;
    }
    text += "; " + std::to_string(event.dropped_sample_count) + " samples\n";
  }
  if (screen.event_count > static_cast<std::int64_t>(screen.events.size())) {
    text += prefix + "  and " + std::to_string(screen.event_count - static_cast<std::int64_t>(screen.events.size())) +
            " more events (counted, not listed)\n";
  }
  return text;
}

std::string format_level_shifts(const std::string& prefix, AllanInput input, const allan::LevelShiftReport& screen) {
  if (!screen.enabled) return prefix + "level-shift screen off: steps in the level, if any, are in the curves\n";
  char line[512];
  std::snprintf(line, sizeof line,
                "level-shift screen (%.3g s windows, threshold %.3g scales): %lld shifts, %lld samples masked%s\n",
                screen.window_s, screen.threshold_sigma, static_cast<long long>(screen.event_count),
                static_cast<long long>(screen.masked_sample_count),
                screen.event_count > 0 ? "; the stepping triad's runs are split at each" : "");
  std::string text = prefix + line;
  const auto from_start_s = [&](std::int64_t stamp_ns) { return seconds_between(screen.first_stamp_ns, stamp_ns); };
  for (std::size_t i = 0; i < screen.events.size(); ++i) {
    const allan::LevelShiftEvent& shift = screen.events[i];
    std::snprintf(line, sizeof line,
                  "  shift %zu: step at %.2f s from the start (stamp %.9f s), masked %.2f-%.2f s:", i + 1,
                  from_start_s(shift.step_stamp_ns), seconds_from_stamp_ns(shift.step_stamp_ns),
                  from_start_s(shift.start_stamp_ns), from_start_s(shift.end_stamp_ns));
    text += prefix + line;
    for (const allan::LevelShiftChannel& channel : shift.channels) {
      std::snprintf(line, sizeof line, " %s %.4g %s (%.1f scales)", kAllanChannelNames.at(channel.channel),
                    channel.shift, allan_value_unit(input, channel.channel), channel.peak_sigma);
      text += line;
    }
    text += "\n";
  }
  if (screen.event_count > static_cast<std::int64_t>(screen.events.size())) {
    text += prefix + "  and " + std::to_string(screen.event_count - static_cast<std::int64_t>(screen.events.size())) +
            " more shifts (counted, not listed)\n";
  }
  return text;
}

std::string format_output_steps(AllanInput input, const std::vector<allan::ChannelOutputStep>& steps) {
  std::string text;
  char value[64];
  for (std::size_t c = 0; c < steps.size() && c < kAllanChannelCount; ++c) {
    if (!text.empty()) text += ", ";
    text += kAllanChannelNames[c];
    if (steps[c].quantised) {
      std::snprintf(value, sizeof value, " %.9g %s", steps[c].step, allan_value_unit(input, c));
      text += value;
    } else {
      text += " none";
    }
  }
  return text;
}

}  // namespace pipeline
}  // namespace imu_lab
