// The most recent phase points of one segment at one pyramid level, addressed by their index in
// the segment (0 = the segment's first point). Stored linearly, not wrapped, so that the
// accumulators can run over a block of new points with plain pointer offsets (x[n], x[n - m],
// ...) that the compiler vectorises; when the storage is full the last `history` points move to
// the front (one copy of `history` doubles every kPhaseBlockPoints pushes).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "imu_lab/allan/checkpoint_codec.h"

namespace imu_lab {
namespace allan {

// Room for new points beyond the kept history at level 0: the most a level appends before its
// accumulators must run (ResolutionLevel), which also bounds the terms of one plain partial sum
// (block_sums.h).
constexpr std::size_t kPhaseBlockPoints = 4096;
// The least room of any level: a few vector iterations per block.
constexpr std::size_t kMinimumPhaseBlockPoints = 64;

// Level L receives a point every 2^L samples, so room for kPhaseBlockPoints / 2^L points has every
// level run its block loops once per kPhaseBlockPoints input samples: the same per-sample
// overhead as level 0, while the room of the many coarse levels a small exact range needs
// (m_exact 64: 16 levels at 400 Hz up to 1e4 s) no longer costs 32 kB each.
inline std::size_t phase_block_points(int level) {
  return std::max(kMinimumPhaseBlockPoints, kPhaseBlockPoints >> std::min(level, 62));
}

class PhaseRing {
 public:
  // history: how many of the newest points stay addressable (the largest reach back plus one);
  // block_points: room for new points beyond it (phase_block_points).
  explicit PhaseRing(std::size_t history, std::size_t block_points = kPhaseBlockPoints)
      : history_(std::max<std::size_t>(history, 1)) {
    values_.assign(history_ + std::max<std::size_t>(block_points, 1), 0.0);
  }

  void clear() {
    count_ = 0;
    first_index_ = 0;
  }
  void push(double phase) {
    if (stored() == values_.size()) compact();
    values_[static_cast<std::size_t>(count_ - first_index_)] = phase;
    ++count_;
  }
  // True when the next push moves the history: points not yet read by the accumulators would
  // lose the history they reach back to, so they must be processed first.
  bool full() const { return stored() == values_.size(); }

  // Valid for count() - history() <= index < count().
  double at(std::int64_t index) const { return values_[static_cast<std::size_t>(index - first_index_)]; }
  // Contiguous from `index` on: point(n)[-j] is point n - j (within the valid range).
  const double* point(std::int64_t index) const { return values_.data() + (index - first_index_); }
  std::int64_t count() const { return count_; }  // phase points pushed since clear()
  std::int64_t newest() const { return count_ - 1; }
  std::int64_t oldest_stored() const { return first_index_; }  // at() and point() reach no further back
  std::size_t history() const { return history_; }
  std::size_t heap_bytes() const { return values_.capacity() * sizeof(double); }

  // Every stored point: new points not yet processed still need the history before them.
  void save(BinaryWriter& out) const {
    out.put_i64(count_);
    out.put_f64s(std::vector<double>(values_.begin(), values_.begin() + stored()));
  }
  void load(BinaryReader& in) {
    count_ = in.get_i64();
    const std::vector<double> stored_points = in.get_finite_f64s();
    if (count_ < 0 || stored_points.size() > values_.size() ||
        stored_points.size() > static_cast<std::size_t>(count_) ||
        stored_points.size() < std::min<std::size_t>(static_cast<std::size_t>(count_), history_)) {
      in.fail("phase window of another length");
    }
    std::copy(stored_points.begin(), stored_points.end(), values_.begin());
    first_index_ = count_ - static_cast<std::int64_t>(stored_points.size());
  }

 private:
  std::size_t stored() const { return static_cast<std::size_t>(count_ - first_index_); }
  void compact() {
    std::copy(values_.end() - static_cast<std::ptrdiff_t>(history_), values_.end(), values_.begin());
    first_index_ = count_ - static_cast<std::int64_t>(history_);
  }

  std::size_t history_;
  std::vector<double> values_;
  std::int64_t first_index_ = 0;  // index of values_[0]
  std::int64_t count_ = 0;
};

// Whether `end` can be where the next block of lag m ends (its first ends at order * m) once the
// points before processed_count are folded in: still the segment's first, or the first past the
// processed points. A checkpoint claiming anything else would reach back before the history.
inline bool is_next_block_end(std::int64_t end, int order, int m, std::int64_t processed_count) {
  const std::int64_t first_end = static_cast<std::int64_t>(order) * m;
  if (end == first_end) return true;
  return end > first_end && (end - first_end) % m == 0 && end >= processed_count && end - processed_count < m;
}

// Reads an accumulator's next block ends, one per averaging factor, refusing any that is not
// is_next_block_end; `what` names them in the refusal.
inline std::vector<std::int64_t> load_next_block_ends(BinaryReader& in, int order,
                                                      const std::vector<int>& averaging_factors,
                                                      std::int64_t processed_count, const std::string& what) {
  std::vector<std::int64_t> ends = in.get_i64s();
  if (ends.size() != averaging_factors.size()) in.fail(what + " for another number of averaging factors");
  for (std::size_t i = 0; i < ends.size(); ++i) {
    if (!is_next_block_end(ends[i], order, averaging_factors[i], processed_count)) {
      in.fail(what + " out of step with the processed points");
    }
  }
  return ends;
}

// Difference of order `order` (2: Allan, 3: Hadamard) at lag m ending at phase index `newest`:
// sum_j (-1)^j C(order, j) x[newest - j m].
inline double phase_difference(const PhaseRing& ring, std::int64_t newest, int m, int order) {
  if (order == 2) return ring.at(newest) - 2.0 * ring.at(newest - m) + ring.at(newest - 2 * m);
  return ring.at(newest) - 3.0 * ring.at(newest - m) + 3.0 * ring.at(newest - 2 * m) - ring.at(newest - 3 * m);
}

}  // namespace allan
}  // namespace imu_lab
