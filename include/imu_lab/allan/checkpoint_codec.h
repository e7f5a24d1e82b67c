// Little binary encoder/decoder for checkpoint payloads: fixed-width values in host byte order
// (a checkpoint is resumed on the machine that wrote it), vectors prefixed by their length.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace imu_lab {
namespace allan {

class BinaryWriter {
 public:
  void put_u64(std::uint64_t value);
  void put_i64(std::int64_t value);
  void put_f64(double value);
  void put_f64s(const std::vector<double>& values);
  void put_i64s(const std::vector<std::int64_t>& values);
  const std::string& bytes() const { return bytes_; }

 private:
  void put_raw(const void* data, std::size_t size);
  std::string bytes_;
};

// Every read checks the remaining length; a short payload throws imu_lab::InputError
// prefixed with `source` (the file name).
class BinaryReader {
 public:
  BinaryReader(const std::string& bytes, std::string source);
  std::uint64_t get_u64();
  std::int64_t get_i64();
  double get_f64();
  std::vector<double> get_f64s();
  std::vector<std::int64_t> get_i64s();
  // Accumulator state is finite and counts are non-negative whenever the engine wrote it; a
  // payload that says otherwise was not written by the engine (or overflowed), and resuming it
  // would turn into NaN statistics or indices outside the buffers.
  double get_finite_f64();
  std::vector<double> get_finite_f64s();
  std::int64_t get_count();
  std::vector<std::int64_t> get_counts();
  // An enumerator stored as its number; anything past `last` is refused.
  template <class Enum>
  Enum get_enum(Enum last, const char* what) {
    const std::int64_t value = get_i64();
    if (value < 0 || value > static_cast<std::int64_t>(last)) fail(std::string("unknown ") + what);
    return static_cast<Enum>(value);
  }
  // Reads a count and checks it against what the caller expects (a shape the options fix).
  void expect_u64(std::uint64_t expected, const char* what);
  bool at_end() const { return position_ == bytes_.size(); }
  std::size_t remaining_bytes() const { return bytes_.size() - position_; }
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  double require_finite(double value) const;
  std::int64_t require_count(std::int64_t count) const;
  void get_raw(void* data, std::size_t size);
  std::size_t get_length(std::size_t element_size);
  const std::string& bytes_;
  std::string source_;
  std::size_t position_ = 0;
};

}  // namespace allan
}  // namespace imu_lab
