// The health of a node's input stream, one implementation for every node's /diagnostics: input
// rate from header stamps against the expected rate, gaps, NaN/Inf samples, duplicate and
// out-of-order stamps, plus the node's own conditions (stale temperature, outside the model...).
// The node checks each sample here and keeps its own policy for what to do with a bad one; once a
// second the diagnostics timer calls fill(), which summarises what happened since the previous
// call (the worst level wins; each problem is named with its count) and lists the totals.
//
// Parameters (private, load_input_health_settings): expected_rate_hz (0: learned as the median of
// the first intervals), gap_factor (the node's default): an interval above gap_factor expected
// intervals is a gap.
#pragma once

#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <ros/node_handle.h>

#include <cstdint>
#include <string>
#include <vector>

#include "imu_lab/ros_io/bag/imu_bag_reader.h"

namespace imu_lab {
namespace ros_io {

struct InputHealthSettings {
  double expected_rate_hz = 0.0;        // 0: learned from the first kLearningIntervals intervals
  double gap_factor = 3.0;              // interval above gap_factor expected intervals: a gap
  double rate_tolerance = 0.05;         // relative rate deviation that warns (a rate change mid-run)
  std::size_t min_rate_intervals = 10;  // fewer intervals in a report window: no rate verdict
};

// Throws ConfigError naming the parameter that is wrong.
InputHealthSettings load_input_health_settings(const ros::NodeHandle& private_node, double default_gap_factor);

enum class StampVerdict {
  kGood,
  kAfterGap,    // in order, but after a gap (counted)
  kDuplicate,   // same stamp as the previous sample (counted)
  kOutOfOrder,  // earlier than the previous sample (counted)
};

class InputHealth {
 public:
  using Level = unsigned char;  // diagnostic_msgs::DiagnosticStatus::OK / WARN / ERROR

  // input: what the node listens to (the topic), named in the messages.
  InputHealth(std::string input, InputHealthSettings settings);

  // One sample by its header stamp: ordering and gaps; the previous stamp only moves forward.
  StampVerdict check_stamp(std::int64_t stamp_ns);
  // A sample with a NaN/Inf value, or one beyond +-1e100 (is_usable_imu_value), counted apart;
  // the node drops or excludes it.
  void count_non_finite() { ++non_finite_.total; }
  void count_too_large() { ++too_large_.total; }
  // Two triads of one sample (rates, or an increment's angle and velocity): counts NaN/Inf or a
  // value beyond +-1e100; true when every value is usable.
  bool check_triads(const Eigen::Vector3d& first, const Eigen::Vector3d& second);
  // A sensor_msgs/Imu sample's values: counts one lacking a triad (covariance[0] = -1, the driver
  // does not provide it), else as check_triads; true when both triads are there and usable.
  bool check_values(const ImuRecord& record);

  // The node's own conditions: define once (returns its id), count per occurrence. A condition
  // with hold_reports > 0 keeps its level for that many further reports after its last
  // occurrence ("<description>: M in all, the last one N reports ago"): an event that marks the whole record (a
  // knock left out of the curves) stays visible to someone who looks a little later.
  std::size_t define_condition(const std::string& description, Level level, int hold_reports = 0);
  void count(std::size_t condition) { ++conditions_.at(condition).count.total; }

  bool rate_known() const { return expected_interval_s_ > 0.0; }
  double expected_rate_hz() const { return rate_known() ? 1.0 / expected_interval_s_ : 0.0; }

  // Summary (worst level since the previous call; ok_message when nothing is wrong) and the
  // totals, then starts a new window. The node may add its own key-values after it.
  void fill(diagnostic_updater::DiagnosticStatusWrapper& status, const std::string& ok_message);

 private:
  struct Count {
    std::uint64_t total = 0;
    std::uint64_t reported = 0;  // total at the previous fill()
    std::uint64_t fresh() const { return total - reported; }
  };
  struct Condition {
    std::string description;
    Level level;
    Count count;
    int hold_reports = 0;
    int reports_since_last = -1;  // -1: never happened
  };
  void learn_interval(double interval_s);

  std::string input_;
  InputHealthSettings settings_;
  double expected_interval_s_ = 0.0;
  bool rate_learned_ = false;  // true once the expected interval came from the data
  std::vector<double> learning_intervals_s_;
  bool have_previous_ = false;
  std::int64_t previous_stamp_ns_ = 0;
  Count samples_, non_finite_, too_large_, absent_triad_, gaps_, duplicates_, out_of_order_;
  double window_gap_s_ = 0.0, longest_gap_s_ = 0.0;
  // Rate from the in-order intervals that are not gaps, so a gap does not look like a slow rate.
  double window_interval_sum_s_ = 0.0;
  std::uint64_t window_interval_count_ = 0;
  double last_rate_hz_ = 0.0;
  std::vector<Condition> conditions_;
};

}  // namespace ros_io
}  // namespace imu_lab
