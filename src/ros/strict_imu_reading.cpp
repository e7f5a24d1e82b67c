#include "imu_lab/ros/strict_imu_reading.h"

#include <cstdio>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace ros_io {
namespace {

std::string seconds_text(std::int64_t stamp_ns) {
  char text[40];
  std::snprintf(text, sizeof text, "%.9f s", stamp_ns * 1e-9);
  return text;
}

}  // namespace

bool StrictImuCheck::accept(const ImuRecord& record) {
  const bool finite = record.angular_rate_rad_s.allFinite() && record.specific_force_m_s2.allFinite();
  const bool in_order = !latest_stamp_ns_ || record.stamp_ns > *latest_stamp_ns_;
  non_finite_ += finite ? 0 : 1;
  unordered_ += in_order ? 0 : 1;
  if ((!finite || !in_order) && !first_bad_stamp_ns_) first_bad_stamp_ns_ = record.stamp_ns;
  if (in_order) latest_stamp_ns_ = record.stamp_ns;
  // From the first bad record on, only count: the caller never sees a bad sample.
  return !first_bad_stamp_ns_;
}

void StrictImuCheck::throw_if_refused(const BagRecording& recording, const std::string& topic) const {
  if (non_finite_ + unordered_ == 0) return;
  throw InputError("bag " + recording.name() + ", topic " + topic + ": " + std::to_string(non_finite_) +
                   " samples with NaN/Inf and " + std::to_string(unordered_) +
                   " stamps not after the previous one (duplicate or out of order), the first at " +
                   seconds_text(*first_bad_stamp_ns_) + "; this tool uses every sample, so nothing was computed or "
                   "written: repair the recording (or cut the bad part out with `rosbag filter`)");
}

std::size_t for_each_imu_strictly(const BagRecording& recording, const std::string& topic,
                                  const std::function<void(const ImuRecord&)>& on_record) {
  StrictImuCheck check;
  const std::size_t count = for_each_imu(recording, topic, [&](const ImuRecord& record) {
    if (check.accept(record)) on_record(record);
  });
  check.throw_if_refused(recording, topic);
  return count;
}

}  // namespace ros_io
}  // namespace imu_lab
