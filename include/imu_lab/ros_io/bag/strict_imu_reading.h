// for_each_imu for tools that use every sample (bag_summary's statistics, the thermal and
// calibration fits, correct): one NaN/Inf value or unordered stamp would silently spoil the result,
// so such a bag is refused with InputError naming the bag, the topic, the counts and the first bad
// stamp. So is a bag whose messages lack a triad the tool needs (covariance[0] = -1, ImuRecord).
// One pass: the callers only gather in on_record and compute and write after it returns, so the
// refusal at the end of the pass still comes before anything is computed or written.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "imu_lab/ros_io/bag/imu_bag_reader.h"

namespace imu_lab {
namespace ros_io {

// The triads a tool cannot do without. One it can do without may be absent from every message
// (the tool then leaves it out, see StrictImuCheck::absent_throughout), not from some of them.
struct ImuTriadsNeeded {
  bool angular_rate = true;
  bool specific_force = true;
};

// The check itself, for a tool that streams the IMU topic together with others (correct).
class StrictImuCheck {
 public:
  explicit StrictImuCheck(ImuTriadsNeeded needed = ImuTriadsNeeded());
  // Counts a NaN/Inf value, a stamp not after the latest one, a missing needed triad; true while
  // no record so far (this one included) was bad, so the caller never uses a sample from the first
  // bad one on.
  bool accept(const ImuRecord& record);
  // Throws the InputError described above if any record was bad, or if a triad the tool can do
  // without is absent from some messages but not all.
  void throw_if_refused(const BagRecording& recording, const std::string& topic) const;
  // After a pass that was not refused: the triads no message carried.
  bool angular_rate_absent_throughout() const { return accepted_ > 0 && absent_rate_ == accepted_; }
  bool specific_force_absent_throughout() const { return accepted_ > 0 && absent_force_ == accepted_; }

 private:
  ImuTriadsNeeded needed_;
  std::size_t non_finite_ = 0, unordered_ = 0, absent_rate_ = 0, absent_force_ = 0, accepted_ = 0;
  std::optional<std::int64_t> latest_stamp_ns_, first_bad_stamp_ns_;
};

// Calls `on_record` in bag order for each message before the first bad one (so for every message
// of a good bag), then throws if there was any. Returns the number of messages. `check` (optional)
// is the check used, for a tool that asks afterwards which triads were absent.
std::size_t for_each_imu_strictly(const BagRecording& recording, const std::string& topic,
                                  const std::function<void(const ImuRecord&)>& on_record,
                                  StrictImuCheck* check = nullptr);

}  // namespace ros_io
}  // namespace imu_lab
