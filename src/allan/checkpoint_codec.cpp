#include "imu_lab/allan/checkpoint_codec.h"

#include <cmath>
#include <cstring>
#include <utility>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace allan {

void BinaryWriter::put_raw(const void* data, std::size_t size) { bytes_.append(static_cast<const char*>(data), size); }
void BinaryWriter::put_u64(std::uint64_t value) { put_raw(&value, sizeof value); }
void BinaryWriter::put_i64(std::int64_t value) { put_raw(&value, sizeof value); }
void BinaryWriter::put_f64(double value) { put_raw(&value, sizeof value); }
void BinaryWriter::put_f64s(const std::vector<double>& values) {
  put_u64(values.size());
  put_raw(values.data(), values.size() * sizeof(double));
}
void BinaryWriter::put_i64s(const std::vector<std::int64_t>& values) {
  put_u64(values.size());
  put_raw(values.data(), values.size() * sizeof(std::int64_t));
}

BinaryReader::BinaryReader(const std::string& bytes, std::string source) : bytes_(bytes), source_(std::move(source)) {}

void BinaryReader::fail(const std::string& problem) const {
  throw InputError(source_ + ": " + problem + " (at byte " + std::to_string(position_) +
                   " of the payload); the checkpoint cannot be resumed, start the run again");
}

void BinaryReader::get_raw(void* data, std::size_t size) {
  if (size == 0) return;  // an empty vector's data() may be null, which memcpy must not see
  if (bytes_.size() - position_ < size) fail("truncated checkpoint payload");
  std::memcpy(data, bytes_.data() + position_, size);
  position_ += size;
}

std::size_t BinaryReader::get_length(std::size_t element_size) {
  const std::uint64_t length = get_u64();
  if (length > (bytes_.size() - position_) / element_size) fail("vector length beyond the payload");
  return static_cast<std::size_t>(length);
}

std::uint64_t BinaryReader::get_u64() {
  std::uint64_t value;
  get_raw(&value, sizeof value);
  return value;
}
std::int64_t BinaryReader::get_i64() {
  std::int64_t value;
  get_raw(&value, sizeof value);
  return value;
}
double BinaryReader::get_f64() {
  double value;
  get_raw(&value, sizeof value);
  return value;
}
std::vector<double> BinaryReader::get_f64s() {
  std::vector<double> values(get_length(sizeof(double)));
  get_raw(values.data(), values.size() * sizeof(double));
  return values;
}
std::vector<std::int64_t> BinaryReader::get_i64s() {
  std::vector<std::int64_t> values(get_length(sizeof(std::int64_t)));
  get_raw(values.data(), values.size() * sizeof(std::int64_t));
  return values;
}
double BinaryReader::require_finite(double value) const {
  if (!std::isfinite(value)) fail("non-finite value in the accumulator state");
  return value;
}
std::int64_t BinaryReader::require_count(std::int64_t count) const {
  if (count < 0) fail("negative count in the accumulator state");
  return count;
}
double BinaryReader::get_finite_f64() { return require_finite(get_f64()); }
std::vector<double> BinaryReader::get_finite_f64s() {
  std::vector<double> values = get_f64s();
  for (const double value : values) require_finite(value);
  return values;
}
std::int64_t BinaryReader::get_count() { return require_count(get_i64()); }
std::vector<std::int64_t> BinaryReader::get_counts() {
  std::vector<std::int64_t> counts = get_i64s();
  for (const std::int64_t count : counts) require_count(count);
  return counts;
}
void BinaryReader::expect_u64(std::uint64_t expected, const char* what) {
  const std::uint64_t found = get_u64();
  if (found != expected) {
    fail(std::string("inconsistent ") + what + ": " + std::to_string(found) + " instead of " +
         std::to_string(expected));
  }
}

}  // namespace allan
}  // namespace imu_lab
