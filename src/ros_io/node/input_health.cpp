#include "imu_lab/ros_io/node/input_health.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "imu_lab/common/stamps.h"
#include "imu_lab/common/usable_imu_values.h"
#include "imu_lab/ros_io/node/node_parameters.h"

namespace imu_lab {
namespace ros_io {
namespace {

// Enough intervals for a median that one late sample cannot move.
constexpr std::size_t kLearningIntervals = 32;
const char* const kTooLargeDescription = "samples with a value beyond +-1e100";

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

InputHealthSettings load_input_health_settings(const ros::NodeHandle& private_node, double default_gap_factor) {
  InputHealthSettings settings;
  settings.expected_rate_hz = parameter(private_node, "expected_rate_hz", 0.0);
  if (!(settings.expected_rate_hz >= 0.0) || !std::isfinite(settings.expected_rate_hz)) {
    throw parameter_error(private_node, "expected_rate_hz",
                          "must be a rate in Hz, or 0 to learn it from the first samples");
  }
  settings.gap_factor = parameter(private_node, "gap_factor", default_gap_factor);
  if (!(settings.gap_factor > 1.0) || !std::isfinite(settings.gap_factor)) {
    throw parameter_error(private_node, "gap_factor", "must be a number above 1");
  }
  return settings;
}

InputHealth::InputHealth(std::string input, InputHealthSettings settings)
    : input_(std::move(input)), settings_(settings) {
  if (settings_.expected_rate_hz > 0.0) expected_interval_s_ = 1.0 / settings_.expected_rate_hz;
}

std::size_t InputHealth::define_condition(const std::string& description, Level level, int hold_reports) {
  conditions_.push_back({description, level, {}, hold_reports});
  return conditions_.size() - 1;
}

void InputHealth::learn_interval(double interval_s) {
  learning_intervals_s_.push_back(interval_s);
  if (learning_intervals_s_.size() < kLearningIntervals) return;
  auto middle = learning_intervals_s_.begin() + learning_intervals_s_.size() / 2;
  std::nth_element(learning_intervals_s_.begin(), middle, learning_intervals_s_.end());
  expected_interval_s_ = *middle;
  rate_learned_ = true;
  learning_intervals_s_.clear();
  learning_intervals_s_.shrink_to_fit();
}

StampVerdict InputHealth::check_stamp(std::int64_t stamp_ns) {
  ++samples_.total;
  if (!have_previous_) {
    have_previous_ = true;
    previous_stamp_ns_ = stamp_ns;
    return StampVerdict::kGood;
  }
  if (stamp_ns == previous_stamp_ns_) {
    ++duplicates_.total;
    return StampVerdict::kDuplicate;
  }
  if (stamp_ns < previous_stamp_ns_) {
    ++out_of_order_.total;
    return StampVerdict::kOutOfOrder;
  }
  const double interval_s = seconds_between(previous_stamp_ns_, stamp_ns);
  previous_stamp_ns_ = stamp_ns;
  if (!rate_known()) {
    learn_interval(interval_s);
    return StampVerdict::kGood;
  }
  if (interval_s > settings_.gap_factor * expected_interval_s_) {
    ++gaps_.total;
    window_gap_s_ += interval_s - expected_interval_s_;
    longest_gap_s_ = std::max(longest_gap_s_, interval_s);
    return StampVerdict::kAfterGap;
  }
  window_interval_sum_s_ += interval_s;
  ++window_interval_count_;
  return StampVerdict::kGood;
}

bool InputHealth::check_values(const ImuRecord& record) {
  if (!record.has_angular_rate || !record.has_specific_force) {
    ++absent_triad_.total;
    return false;
  }
  return check_triads(record.angular_rate_rad_s, record.specific_force_m_s2);
}

bool InputHealth::check_triads(const Eigen::Vector3d& first, const Eigen::Vector3d& second) {
  if (!first.allFinite() || !second.allFinite()) {
    ++non_finite_.total;
    return false;
  }
  if (!is_usable_imu_vector(first) || !is_usable_imu_vector(second)) {
    ++too_large_.total;
    return false;
  }
  return true;
}

void InputHealth::fill(diagnostic_updater::DiagnosticStatusWrapper& status, const std::string& ok_message) {
  using diagnostic_msgs::DiagnosticStatus;
  Level level = DiagnosticStatus::OK;
  std::string problems;
  const auto note = [&](Level problem_level, const std::string& text) {
    level = std::max(level, problem_level);
    problems += (problems.empty() ? "" : "; ") + text;
  };
  if (samples_.fresh() == 0) note(DiagnosticStatus::WARN, "no input on " + input_ + " since the last report");
  if (non_finite_.fresh() > 0)
    note(DiagnosticStatus::WARN, std::to_string(non_finite_.fresh()) + " samples with NaN/Inf");
  if (too_large_.fresh() > 0) {
    note(DiagnosticStatus::WARN, std::to_string(too_large_.fresh()) + " " + kTooLargeDescription);
  }
  if (absent_triad_.fresh() > 0) {
    note(DiagnosticStatus::WARN, std::to_string(absent_triad_.fresh()) +
                                     " samples without angular rate or specific "
                                     "force (covariance[0] = -1)");
  }
  if (gaps_.fresh() > 0) {
    note(DiagnosticStatus::WARN,
         std::to_string(gaps_.fresh()) + " gaps in the stamps (" + format("%.3f", window_gap_s_) + " s missing)");
  }
  if (duplicates_.fresh() > 0) note(DiagnosticStatus::WARN, std::to_string(duplicates_.fresh()) + " duplicate stamps");
  if (out_of_order_.fresh() > 0) {
    note(DiagnosticStatus::WARN, std::to_string(out_of_order_.fresh()) + " out-of-order stamps");
  }
  last_rate_hz_ = window_interval_count_ > 0 ? window_interval_count_ / window_interval_sum_s_ : 0.0;
  if (rate_known() && window_interval_count_ >= settings_.min_rate_intervals &&
      std::abs(last_rate_hz_ * expected_interval_s_ - 1.0) > settings_.rate_tolerance) {
    note(DiagnosticStatus::WARN,
         "input rate " + format("%.4g", last_rate_hz_) + " Hz, expected " + format("%.4g", expected_rate_hz()) + " Hz");
  }
  for (Condition& condition : conditions_) {
    if (condition.count.fresh() > 0) {
      note(condition.level, std::to_string(condition.count.fresh()) + " " + condition.description);
      condition.reports_since_last = 0;
    } else if (condition.reports_since_last >= 0 && condition.reports_since_last < condition.hold_reports) {
      ++condition.reports_since_last;
      note(condition.level, condition.description + ": " + std::to_string(condition.count.total) +
                                " in all, the last one " + std::to_string(condition.reports_since_last) +
                                " reports ago");
    }
  }
  status.summary(level, problems.empty() ? ok_message : problems);

  status.add("input", input_);
  status.add("input rate from stamps [Hz]", last_rate_hz_);
  status.add("expected rate [Hz]", rate_known()
                                       ? format("%.6g", expected_rate_hz()) + (rate_learned_ ? " (learned)" : "")
                                       : std::string("learning"));
  status.add("samples", samples_.total);
  status.add("NaN/Inf samples", non_finite_.total);
  status.add(kTooLargeDescription, too_large_.total);
  status.add("samples without a triad (covariance[0] = -1)", absent_triad_.total);
  status.add("gaps", gaps_.total);
  status.add("longest gap [s]", longest_gap_s_);
  status.add("duplicate stamps", duplicates_.total);
  status.add("out-of-order stamps", out_of_order_.total);
  for (const Condition& condition : conditions_) status.add(condition.description, condition.count.total);

  for (Count* count : {&samples_, &non_finite_, &too_large_, &absent_triad_, &gaps_, &duplicates_, &out_of_order_}) {
    count->reported = count->total;
  }
  for (Condition& condition : conditions_) condition.count.reported = condition.count.total;
  window_gap_s_ = 0.0;
  window_interval_sum_s_ = 0.0;
  window_interval_count_ = 0;
}

}  // namespace ros_io
}  // namespace imu_lab
