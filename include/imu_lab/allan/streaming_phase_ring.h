// The most recent phase points of one segment at one pyramid level, addressed by their index in
// the segment (0 = the segment's first point). Capacity is a power of two so indexing is a mask.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "imu_lab/allan/checkpoint_codec.h"

namespace imu_lab {
namespace allan {

class PhaseRing {
 public:
  explicit PhaseRing(std::size_t min_capacity) {
    std::size_t capacity = 1;
    while (capacity < min_capacity) capacity *= 2;
    values_.assign(capacity, 0.0);
    mask_ = capacity - 1;
  }

  void clear() { count_ = 0; }
  void push(double phase) { values_[static_cast<std::size_t>(count_) & mask_] = phase; ++count_; }

  // Valid for count() - capacity() <= index < count().
  double at(std::int64_t index) const { return values_[static_cast<std::size_t>(index) & mask_]; }
  std::int64_t count() const { return count_; }  // phase points pushed since clear()
  std::int64_t newest() const { return count_ - 1; }
  std::size_t capacity() const { return values_.size(); }
  std::size_t heap_bytes() const { return values_.capacity() * sizeof(double); }

  void save(BinaryWriter& out) const {
    out.put_i64(count_);
    out.put_f64s(values_);
  }
  void load(BinaryReader& in) {
    count_ = in.get_i64();
    std::vector<double> values = in.get_f64s();
    if (values.size() != values_.size() || count_ < 0) in.fail("phase ring of another capacity");
    values_ = std::move(values);
  }

 private:
  std::vector<double> values_;
  std::size_t mask_ = 0;
  std::int64_t count_ = 0;
};

// Difference of order `order` (2: Allan, 3: Hadamard) at lag m ending at phase index `newest`:
// sum_j (-1)^j C(order, j) x[newest - j m].
inline double phase_difference(const PhaseRing& ring, std::int64_t newest, int m, int order) {
  if (order == 2) return ring.at(newest) - 2.0 * ring.at(newest - m) + ring.at(newest - 2 * m);
  return ring.at(newest) - 3.0 * ring.at(newest - m) + 3.0 * ring.at(newest - 2 * m) -
         ring.at(newest - 3 * m);
}

}  // namespace allan
}  // namespace imu_lab
