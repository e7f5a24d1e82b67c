#include "imu_lab/ros/allan_summary.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>

namespace imu_lab {
namespace ros_io {
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

void emit_timing(YAML::Emitter& out, const allan::TimingReport& timing, bool stop_policy) {
  out << YAML::Key << "tau0_s" << YAML::Value << timing.tau0_s;
  out << YAML::Key << "sample_rate_hz" << YAML::Value << (timing.tau0_s > 0.0 ? 1.0 / timing.tau0_s : 0.0);
  out << YAML::Key << "interval_rms_deviation_s" << YAML::Value << timing.interval_rms_deviation_s;
  out << YAML::Key << "interval_max_deviation_s" << YAML::Value << timing.interval_max_deviation_s;
  out << YAML::Key << "stamp_policy" << YAML::Value << (stop_policy ? "stop" : "split_and_pool");
  emit_irregularity(out, "gaps", timing.gap_count, "run split at each gap, the segments' sums pooled");
  out << YAML::Key << "gap_time_s" << YAML::Value << timing.gap_time_s;
  emit_irregularity(out, "duplicates", timing.duplicate_count, "samples dropped");
  emit_irregularity(out, "out_of_order", timing.out_of_order_count, "samples dropped");
  out << YAML::Key << "first_stamp_events" << YAML::Value << YAML::BeginSeq;
  for (std::size_t i = 0; i < std::min(timing.events.size(), kListedStampEvents); ++i) {
    const allan::StampEvent& event = timing.events[i];
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "kind" << YAML::Value << event_name(event.kind)
        << YAML::Key << "sample_index" << YAML::Value << event.sample_index << YAML::Key << "stamp_ns" << YAML::Value
        << event.stamp_ns << YAML::Key << "previous_stamp_ns" << YAML::Value << event.previous_stamp_ns
        << YAML::EndMap;
  }
  out << YAML::EndSeq;
}

void emit_channels(YAML::Emitter& out, const AllanRunDescription& run, const allan::StreamingSnapshot& snapshot) {
  // An increment's offset is per sample; the summary gives it as a rate like the curves.
  const double offset_scale = run.input == AllanInput::kIncrement && snapshot.timing.tau0_s > 0.0
                                  ? 1.0 / snapshot.timing.tau0_s
                                  : 1.0;
  std::int64_t non_finite_total = 0;
  out << YAML::Key << "channels" << YAML::Value << YAML::BeginMap;
  for (std::size_t c = 0; c < snapshot.channels.size() && c < kAllanChannelCount; ++c) {
    const allan::ChannelReport& report = snapshot.channels[c];
    const std::string unit = kAllanChannelUnits[c];
    non_finite_total += report.non_finite_count;
    out << YAML::Key << kAllanChannelNames[c] << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "offset_" + unit << YAML::Value << report.offset * offset_scale;
    out << YAML::Key << "finite_samples" << YAML::Value << report.finite_sample_count;
    out << YAML::Key << "non_finite_samples" << YAML::Value << report.non_finite_count;
    out << YAML::Key << "segments" << YAML::Value << report.segment_count;
    const allan::StabilityPoint* minimum =
        minimum_point(snapshot.curve(allan::Statistic::kOverlappingAllan, c));
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

}  // namespace

const allan::StabilityPoint* minimum_point(const std::vector<allan::StabilityPoint>& curve) {
  const auto smallest = std::min_element(curve.begin(), curve.end(), [](const auto& a, const auto& b) {
    return a.deviation < b.deviation;
  });
  return smallest == curve.end() ? nullptr : &*smallest;
}

std::string format_allan_summary(const AllanRunDescription& run, const allan::StreamingSnapshot& snapshot) {
  YAML::Emitter out;
  out.SetDoublePrecision(15);  // tau0 0.005, not 0.0050000000000000001
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << "imu_lab_allan_summary";
  if (!run.bag.empty()) out << YAML::Key << "bag" << YAML::Value << run.bag;
  out << YAML::Key << "topic" << YAML::Value << run.topic;
  out << YAML::Key << "input" << YAML::Value << allan_input_name(run.input);
  out << YAML::Key << "message_type" << YAML::Value << allan_input_datatype(run.input);
  out << YAML::Key << "samples" << YAML::Value << snapshot.timing.input_sample_count;
  out << YAML::Key << "accepted_samples" << YAML::Value << snapshot.timing.accepted_sample_count;
  if (run.skipped_before_checkpoint > 0) {
    out << YAML::Key << "skipped_before_checkpoint" << YAML::Value << run.skipped_before_checkpoint;
  }
  emit_timing(out, snapshot.timing, run.engine.stamp_policy == allan::StampPolicy::kStop);
  emit_channels(out, run, snapshot);
  out << YAML::Key << "confidence" << YAML::Value << run.engine.confidence;
  out << YAML::Key << "points_per_decade" << YAML::Value << run.engine.points_per_decade;
  out << YAML::Key << "max_tau_s" << YAML::Value << run.engine.max_tau_s;
  out << YAML::Key << "exact_max_averaging_factor" << YAML::Value << run.engine.exact_max_averaging_factor;
  out << YAML::Key << "gap_factor" << YAML::Value << run.engine.gap_factor;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace ros_io
}  // namespace imu_lab
