#include "imu_lab/ros/strict_imu_reading.h"

#include <cstdint>
#include <cstdio>
#include <optional>

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

std::size_t for_each_imu_strictly(const std::string& bag_path, const std::string& topic,
                                  const std::function<void(const ImuRecord&)>& on_record) {
  std::size_t non_finite = 0, unordered = 0;
  std::optional<std::int64_t> latest_stamp_ns, first_bad_stamp_ns;
  const std::size_t count = for_each_imu(bag_path, topic, [&](const ImuRecord& record) {
    const bool finite = record.angular_rate_rad_s.allFinite() && record.specific_force_m_s2.allFinite();
    const bool in_order = !latest_stamp_ns || record.stamp_ns > *latest_stamp_ns;
    non_finite += finite ? 0 : 1;
    unordered += in_order ? 0 : 1;
    if ((!finite || !in_order) && !first_bad_stamp_ns) first_bad_stamp_ns = record.stamp_ns;
    if (in_order) latest_stamp_ns = record.stamp_ns;
    // From the first bad record on, only count: the caller never sees a bad sample.
    if (!first_bad_stamp_ns) on_record(record);
  });
  if (non_finite + unordered > 0) {
    throw InputError("bag " + bag_path + ", topic " + topic + ": " + std::to_string(non_finite) +
                     " samples with NaN/Inf and " + std::to_string(unordered) +
                     " stamps not after the previous one (duplicate or out of order), the first at " +
                     seconds_text(*first_bad_stamp_ns) + "; this tool uses every sample, so nothing was computed or "
                     "written: repair the recording (or cut the bad part out with `rosbag filter`)");
  }
  return count;
}

}  // namespace ros_io
}  // namespace imu_lab
