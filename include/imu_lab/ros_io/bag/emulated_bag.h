// Runs the emulator for a duration and writes its messages into a bag (atomically), at full
// machine speed. The emulate tool, the tests and the benchmarks share it.
#pragma once

#include <cstdint>
#include <string>

#include "imu_lab/common/progress.h"
#include "imu_lab/emulator/imu_emulator.h"
#include "imu_lab/ros_io/msg/emulator_messages.h"

namespace imu_lab {
namespace ros_io {

struct EmulatedBagOptions {
  double duration_s = 60.0;
  std::string frame_id = "imu_link";
  EmulatorTopics topics;
  bool write_temperature = true;
  bool write_truth = true;
  bool write_increments = true;
  ProgressCallback on_progress;  // (samples written, samples in the run); empty: nothing told
};

// Returns the number of samples written. Throws (ConfigError / std::runtime_error) with a clear
// message; on any failure no bag is left at `bag_path`.
std::uint64_t write_emulated_bag(emulator::ImuEmulator& emulator, const EmulatedBagOptions& options,
                                 const std::string& bag_path);

}  // namespace ros_io
}  // namespace imu_lab
