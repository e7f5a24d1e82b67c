// libFuzzer harness: the YAML column mapping of a logger's CSV (io/csv_import_config.h).
#include "fuzz_loader.h"
#include "imu_lab/io/csv_import_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  return imu_lab::fuzz::refusals_allowed([&] { imu_lab::io::parse_csv_import_options(text, "fuzz.yaml"); });
}
