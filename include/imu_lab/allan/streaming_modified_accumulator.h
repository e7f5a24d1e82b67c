// Modified Allan terms over a block of new phase points at a time: the term starting at j is the
// sum of the m second differences x[i+2m] - 2 x[i+m] + x[i], i = j .. j+m-1. A moving window sum
// per factor adds the newest second difference and drops the oldest, which is adding the third
// difference x[n] - 3 x[n-m] + 3 x[n-2m] - x[n-3m]; it is recomputed exactly from the ring every
// few windows so rounding cannot drift over 1e8 updates.
#pragma once

#include <cstdint>
#include <vector>

#include "imu_lab/allan/streaming_difference_sums.h"
#include "imu_lab/allan/streaming_phase_ring.h"

namespace imu_lab {
namespace allan {

class ModifiedAccumulator {
 public:
  // averaging_factors ascending; the ring must hold 3 * max(m) + 1 points.
  explicit ModifiedAccumulator(std::vector<int> averaging_factors);

  void start_segment();
  // Every phase point from first_index to ring.newest(); the ring must still hold 3 max(m)
  // points before first_index.
  void update(const PhaseRing& ring, std::int64_t first_index);

  // squares: sum of squared window sums; count: number of terms (N - 3m + 1 per segment).
  const DifferenceSums& terms(std::size_t tau_index) const { return terms_[tau_index]; }
  std::size_t heap_bytes() const;

  void save(BinaryWriter& out) const;
  void load(BinaryReader& in);

 private:
  // The window of the m second differences ending at phase index `end`.
  static double exact_window_sum(const PhaseRing& ring, std::int64_t end, int m);

  std::vector<int> averaging_factors_;
  std::vector<DifferenceSums> terms_;
  std::vector<double> window_sums_;
  std::vector<std::int64_t> updates_since_exact_;
};

}  // namespace allan
}  // namespace imu_lab
