#include "imu_lab/ros_io/bag/emulated_bag.h"

#include <cmath>
#include <stdexcept>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/format_number.h"
#include "imu_lab/ros_io/bag/atomic_bag.h"

namespace imu_lab {
namespace ros_io {
namespace {

constexpr double kLastRosTime_s = 4294967295.0;

}  // namespace

std::uint64_t write_emulated_bag(emulator::ImuEmulator& emulator, const EmulatedBagOptions& options,
                                 const std::string& bag_path) {
  const char* const kSource = "emulated run";
  if (!(options.duration_s > 0.0) || !std::isfinite(options.duration_s)) {
    throw ConfigError(kSource, "duration_s",
                      "must be a finite number of seconds > 0, got " + format_number(options.duration_s, 6));
  }
  const double interval_s = emulator.sample_interval_s();
  const double samples = options.duration_s / interval_s;
  if (!(samples >= 0.5)) {
    throw ConfigError(kSource, "duration_s x rate_hz",
                      format_number(options.duration_s, 6) + " s at " + format_number(emulator.settings().rate_hz, 6) +
                          " Hz holds no sample (" + format_number(samples, 3) + "); raise the rate or the duration");
  }
  // ROS stamps are unsigned 32-bit seconds (rosbag refuses later ones).
  const double end_s = emulator.settings().start_time_s + options.duration_s;
  if (!(end_s <= kLastRosTime_s)) {
    throw ConfigError(kSource, "start_time_s + duration_s",
                      "the run would end at " + format_number(end_s, 6) + " s, beyond ROS time (stamps end at " +
                          format_number(kLastRosTime_s, 10) + " s, in 2106)");
  }
  const auto sample_count = static_cast<std::uint64_t>(std::llround(samples));
  AtomicBag bag(bag_path);
  for (std::uint64_t i = 0; i < sample_count; ++i) {
    const emulator::EmulatedSample sample = emulator.next();
    const EmulatorMessages messages = to_messages(sample, interval_s, options.frame_id);
    const ros::Time& stamp = messages.raw.header.stamp;
    bag.write(options.topics.raw, stamp, messages.raw);
    if (options.write_temperature) {
      bag.write(options.topics.temperature, stamp, messages.temperature);
      if (messages.second_temperature)
        bag.write(options.topics.second_temperature, stamp, *messages.second_temperature);
    }
    if (options.write_truth) bag.write(options.topics.truth, stamp, messages.truth);
    if (options.write_increments) bag.write(options.topics.increment, stamp, messages.increment);
    if (options.on_progress) options.on_progress(i + 1, sample_count);
  }
  bag.commit();
  return sample_count;
}

}  // namespace ros_io
}  // namespace imu_lab
