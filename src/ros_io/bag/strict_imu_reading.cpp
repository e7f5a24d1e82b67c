#include "imu_lab/ros_io/bag/strict_imu_reading.h"

#include <cstdio>
#include <vector>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/common/usable_imu_values.h"

namespace imu_lab {
namespace ros_io {
namespace {

const char* const kNoDataMark = "covariance[0] = -1, sensor_msgs/Imu's mark for a triad the driver does not provide";

}  // namespace

StrictImuCheck::StrictImuCheck(ImuTriadsNeeded needed) : needed_(needed) {}

bool StrictImuCheck::accept(const ImuRecord& record) {
  // An absent triad's values are NaN by design: it is judged by its flag, not its values.
  const bool finite = (!record.has_angular_rate || is_usable_imu_vector(record.angular_rate_rad_s)) &&
                      (!record.has_specific_force || is_usable_imu_vector(record.specific_force_m_s2));
  const bool in_order = !latest_stamp_ns_ || record.stamp_ns > *latest_stamp_ns_;
  const bool needed_missing =
      (!record.has_angular_rate && needed_.angular_rate) || (!record.has_specific_force && needed_.specific_force);
  non_finite_ += finite ? 0 : 1;
  unordered_ += in_order ? 0 : 1;
  absent_rate_ += record.has_angular_rate ? 0 : 1;
  absent_force_ += record.has_specific_force ? 0 : 1;
  ++accepted_;
  if ((!finite || !in_order || needed_missing) && !first_bad_stamp_ns_) first_bad_stamp_ns_ = record.stamp_ns;
  if (in_order) latest_stamp_ns_ = record.stamp_ns;
  // From the first bad record on, only count: the caller never sees a bad sample.
  return !first_bad_stamp_ns_;
}

void StrictImuCheck::throw_if_refused(const BagRecording& recording, const std::string& topic) const {
  std::vector<std::string> problems;
  if (non_finite_ + unordered_ > 0) {
    problems.push_back(std::to_string(non_finite_) + " samples with NaN/Inf (or beyond +-1e100) and " +
                       std::to_string(unordered_) + " stamps not after the previous one (duplicate or out of order)");
  }
  const auto absent = [&](std::size_t count, bool needed, const char* what) {
    if (count == 0 || (!needed && count == accepted_)) return;
    problems.push_back(std::to_string(count) + " of " + std::to_string(accepted_) + " messages without " + what + " (" +
                       kNoDataMark + ")" + (needed ? "" : ", the others with it"));
  };
  absent(absent_rate_, needed_.angular_rate, "angular rate");
  absent(absent_force_, needed_.specific_force, "specific force");
  if (problems.empty()) return;
  std::string text;
  for (const std::string& problem : problems) text += (text.empty() ? "" : "; ") + problem;
  const std::string first = first_bad_stamp_ns_ ? ", the first at " + format_stamp_s(*first_bad_stamp_ns_) + " s" : "";
  throw InputError("bag " + recording.name() + ", topic " + topic + ": " + text + first +
                   "; this tool uses every sample, so nothing was computed or written: repair the "
                   "recording (or cut the bad part out with `rosbag filter`)");
}

std::size_t for_each_imu_strictly(const BagRecording& recording, const std::string& topic,
                                  const std::function<void(const ImuRecord&)>& on_record, StrictImuCheck* check) {
  StrictImuCheck own_check;
  StrictImuCheck& used = check != nullptr ? *check : own_check;
  const std::size_t count = for_each_imu(recording, topic, [&](const ImuRecord& record) {
    if (used.accept(record)) on_record(record);
  });
  used.throw_if_refused(recording, topic);
  return count;
}

}  // namespace ros_io
}  // namespace imu_lab
