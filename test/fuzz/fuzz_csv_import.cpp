// libFuzzer harness: the logger-CSV parser (io/csv_imu_import.h). The first byte picks one of a
// few column mappings (header names or numbers, delimiters, decimal comma, units, a temperature
// column, a large time offset), and whether to infer from the header as import_csv does; the rest is
// the file. Bad rows are reported, not thrown: the
// parser may only throw ConfigError for a mapping that does not fit the file.
#include <array>

#include "fuzz_loader.h"
#include "imu_lab/io/csv_imu_import.h"

namespace {

using imu_lab::io::CsvImportOptions;

std::array<CsvImportOptions, 4> mappings() {
  std::array<CsvImportOptions, 4> options;
  options[1].time_column = "t";
  options[1].gyro_columns = {"gx", "gy", "gz"};
  options[1].accel_columns = {"ax", "ay", "az"};
  options[1].temperature_column = "temp";
  options[1].time_unit = imu_lab::io::TimeUnit::kMillisecond;
  options[1].gyro_unit = imu_lab::io::AngularRateUnit::kDegreePerSecond;
  options[1].accel_unit = imu_lab::io::SpecificForceUnit::kStandardGravity;
  options[2].delimiter = ';';
  options[2].decimal_comma = true;
  options[2].has_header = false;
  options[2].temperature_column = "8";
  options[2].time_unit = imu_lab::io::TimeUnit::kNanosecond;
  options[2].bad_rows = imu_lab::io::BadRowPolicy::kSkip;
  options[3].delimiter = '\t';
  options[3].has_header = false;
  options[3].time_unit = imu_lab::io::TimeUnit::kMicrosecond;
  options[3].time_offset_ns = 1700000000LL * 1000000000LL;
  options[3].max_reported_rows = 2;
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const std::array<CsvImportOptions, 4> options = mappings();
  CsvImportOptions mapping = options[data[0] % options.size()];
  // Bit 2 of the first byte: read as import_csv does (units and columns from the header, a
  // relative time column moved), so the header inference meets every header too.
  mapping.infer_from_file = (data[0] / options.size()) % 2 == 1;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  return imu_lab::fuzz::refusals_allowed(
      [&] { imu_lab::io::parse_imu_csv_text(text, mapping).summary.describe_rejections("fuzz.csv"); });
}
