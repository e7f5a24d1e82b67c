// libFuzzer harness: the sensor-profile YAML loader (emulator/sensor_profile.h).
#include "fuzz_loader.h"
#include "imu_lab/emulator/sensor_profile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return imu_lab::fuzz::refusals_allowed(
      [&] { imu_lab::emulator::load_sensor_profile(imu_lab::fuzz::input_file_path(data, size)); });
}
