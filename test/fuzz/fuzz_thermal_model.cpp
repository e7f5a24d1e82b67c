// libFuzzer harness: the thermal model YAML loader (thermal/thermal_model_yaml.h).
#include "fuzz_loader.h"
#include "imu_lab/thermal/thermal_model_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return imu_lab::fuzz::refusals_allowed(
      [&] { imu_lab::thermal::load_thermal_model(imu_lab::fuzz::input_file_path(data, size)); });
}
