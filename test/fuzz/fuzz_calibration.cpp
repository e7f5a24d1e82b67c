// libFuzzer harness: the calibration YAML loader (calib/calibration_file.h).
#include "fuzz_loader.h"
#include "imu_lab/calib/calibration_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return imu_lab::fuzz::refusals_allowed(
      [&] { imu_lab::calib::load_calibration(imu_lab::fuzz::input_file_path(data, size)); });
}
