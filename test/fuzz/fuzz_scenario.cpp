// libFuzzer harness: the scenario YAML loader (emulator/scenario.h).
#include "fuzz_loader.h"
#include "imu_lab/emulator/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return imu_lab::fuzz::refusals_allowed(
      [&] { imu_lab::emulator::load_scenario(imu_lab::fuzz::input_file_path(data, size)); });
}
