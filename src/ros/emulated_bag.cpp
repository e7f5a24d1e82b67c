#include "imu_lab/ros/emulated_bag.h"

#include <cmath>
#include <stdexcept>

#include "imu_lab/ros/atomic_bag.h"

namespace imu_lab {
namespace ros_io {

std::uint64_t write_emulated_bag(emulator::ImuEmulator& emulator, const EmulatedBagOptions& options,
                                 const std::string& bag_path) {
  if (!(options.duration_s > 0.0) || !std::isfinite(options.duration_s)) {
    throw std::invalid_argument("duration must be a positive number of seconds, got " +
                                std::to_string(options.duration_s));
  }
  const double interval_s = emulator.sample_interval_s();
  const auto sample_count = static_cast<std::uint64_t>(std::llround(options.duration_s / interval_s));
  AtomicBag bag(bag_path);
  for (std::uint64_t i = 0; i < sample_count; ++i) {
    const emulator::ImuSample sample = emulator.next();
    const ros::Time stamp = sample_stamp(emulator.settings().start_time_s, interval_s, emulator.samples_emitted());
    const EmulatorMessages messages = to_messages(sample, stamp, interval_s, options.frame_id);
    bag.write(options.topics.raw, stamp, messages.raw);
    if (options.write_temperature) {
      bag.write(options.topics.temperature, stamp, messages.temperature);
      if (messages.second_temperature) bag.write(options.topics.second_temperature, stamp, *messages.second_temperature);
    }
    if (options.write_truth) bag.write(options.topics.truth, stamp, messages.truth);
    if (options.write_increments) bag.write(options.topics.increment, stamp, messages.increment);
  }
  bag.commit();
  return sample_count;
}

}  // namespace ros_io
}  // namespace imu_lab
