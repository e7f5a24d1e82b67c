// for_each_imu for tools that use every sample (bag_summary's statistics, the thermal and
// calibration fits): one NaN/Inf value or unordered stamp would silently spoil the result, so such
// a bag is refused with InputError naming the bag, the topic, the counts and the first bad stamp.
// One pass: the callers only gather in on_record and compute and write after it returns, so the
// refusal at the end of the pass still comes before anything is computed or written.
#pragma once

#include <functional>
#include <string>

#include "imu_lab/ros/imu_bag_reader.h"

namespace imu_lab {
namespace ros_io {

// Calls `on_record` in bag order for each message before the first bad one (so for every message
// of a good bag), then throws if there was any. Returns the number of messages.
std::size_t for_each_imu_strictly(const std::string& bag_path, const std::string& topic,
                                  const std::function<void(const ImuRecord&)>& on_record);

}  // namespace ros_io
}  // namespace imu_lab
