#include "imu_lab/allan/streaming_modified_accumulator.h"

#include <algorithm>
#include <utility>

namespace imu_lab {
namespace allan {
namespace {

// Recomputing costs m ring reads; every 16 windows it adds ~6% to the update cost.
constexpr std::int64_t kWindowsBetweenExactSums = 16;

}  // namespace

ModifiedAccumulator::ModifiedAccumulator(std::vector<int> averaging_factors)
    : averaging_factors_(std::move(averaging_factors)),
      terms_(averaging_factors_.size()),
      window_sums_(averaging_factors_.size()),
      updates_since_exact_(averaging_factors_.size()) {
  start_segment();
}

void ModifiedAccumulator::start_segment() {
  std::fill(window_sums_.begin(), window_sums_.end(), 0.0);
  std::fill(updates_since_exact_.begin(), updates_since_exact_.end(), 0);
}

double ModifiedAccumulator::exact_window_sum(const PhaseRing& ring, std::int64_t end, int m) {
  double sum = 0.0;
  for (std::int64_t last = end - m + 1; last <= end; ++last) sum += phase_difference(ring, last, m, 2);
  return sum;
}

namespace {

// LaneVector helpers are inlined into the block loops: no vector crosses a call (see
// streaming_block_sums.h on -Wpsabi). Off to the end of this file, where GCC reports it.
#pragma GCC diagnostic ignored "-Wpsabi"

// [v0, v0 + v1, v0 + v1 + v2, v0 + v1 + v2 + v3] in two shift-and-add steps.
inline LaneVector running_sums(const LaneVector& steps) {
  const LaneVector zero = {};
  const LaneVector pairs = steps + __builtin_shufflevector(zero, steps, 0, 4, 5, 6);
  return pairs + __builtin_shufflevector(zero, pairs, 0, 1, 4, 5);
}

// Slides the window over the phase points ending at x[0] .. x[count - 1] (each a full-window
// position) and sums the windows into `out`. Four steps at a time: their
// running sums do not depend on the window, so the serial chain is one addition per four
// windows instead of one per window. Each window is still the previous one plus at most four
// third differences, rounded a few times: the same few-ulp drift per step as one at a time,
// reset by the exact sum every kWindowsBetweenExactSums m windows.
IMU_LAB_ALLAN_BLOCK_LOOP
double slide_window(const double* x, std::int64_t count, std::ptrdiff_t m, double window, BlockSums& out) {
  BlockSums terms;  // a local, so the lanes stay in registers
  std::int64_t k = 0;
  for (; k + BlockSums::kLanes <= count; k += BlockSums::kLanes) {
    const double* p = x + k;
    const LaneVector steps =
        load_lanes(p) - 3.0 * load_lanes(p - m) + 3.0 * load_lanes(p - 2 * m) - load_lanes(p - 3 * m);
    const LaneVector sums = running_sums(steps);
    terms.add(broadcast_lane(window) + sums);
    // The last lane's addition again, as a scalar: the same rounding, so the same bits, but the
    // serial chain from one window to the next is one scalar addition instead of a vector
    // addition, a lane extraction and a broadcast.
    window += sums[BlockSums::kLanes - 1];
  }
  for (; k < count; ++k) {
    const double* p = x + k;
    window += p[0] - 3.0 * p[-m] + 3.0 * p[-2 * m] - p[-3 * m];
    terms.add(0, window);
  }
  terms.count = count;
  out = terms;
  return window;
}

}  // namespace

void ModifiedAccumulator::update(const PhaseRing& ring, std::int64_t first_index) {
  const std::int64_t newest = ring.newest();
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    const std::int64_t m = averaging_factors_[i];
    if (newest < 2 * m) break;  // no second difference yet (nor for the larger factors)
    double& window = window_sums_[i];
    std::int64_t& since_exact = updates_since_exact_[i];
    DifferenceSums& terms = terms_[i];
    std::int64_t n = std::max(first_index, 2 * m);
    // The first m second differences of a segment fill the window; the first term ends at 3m - 1.
    for (; n <= newest && n < 3 * m; ++n) {
      window += phase_difference(ring, n, static_cast<int>(m), 2);
      if (n < 3 * m - 1) continue;
      ++since_exact;
      terms.add(window);
    }
    const std::int64_t exact_every = kWindowsBetweenExactSums * m;
    while (n <= newest) {
      const std::int64_t slid = std::min(newest - n + 1, exact_every - 1 - since_exact);
      if (slid < BlockSums::kLanes) {
        // A few points (push() of one sample): per-term compensated sums cost less than a block.
        for (std::int64_t end = n; end < n + slid; ++end) {
          window += phase_difference(ring, end, static_cast<int>(m), 3);
          terms.add(window);
        }
      } else {
        BlockSums block;
        window = slide_window(ring.point(n), slid, static_cast<std::ptrdiff_t>(m), window, block);
        terms.add_block(block);
      }
      n += slid;
      since_exact += slid;
      if (n > newest) break;
      window = exact_window_sum(ring, n, static_cast<int>(m));
      since_exact = 0;
      terms.add(window);
      ++n;
    }
  }
}

std::size_t ModifiedAccumulator::heap_bytes() const {
  return averaging_factors_.capacity() * sizeof(int) + terms_.capacity() * sizeof(DifferenceSums) +
         window_sums_.capacity() * sizeof(double) + updates_since_exact_.capacity() * sizeof(std::int64_t);
}

void ModifiedAccumulator::save(BinaryWriter& out) const {
  out.put_u64(averaging_factors_.size());
  for (const DifferenceSums& sums : terms_) sums.save(out);
  out.put_f64s(window_sums_);
  out.put_i64s(updates_since_exact_);
}

void ModifiedAccumulator::load(BinaryReader& in) {
  in.expect_u64(averaging_factors_.size(), "number of averaging factors");
  for (DifferenceSums& sums : terms_) sums.load(in);
  window_sums_ = in.get_finite_f64s();
  updates_since_exact_ = in.get_counts();
  if (window_sums_.size() != averaging_factors_.size() || updates_since_exact_.size() != averaging_factors_.size()) {
    in.fail("modified Allan window count");
  }
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    // update() slides at most exact_every - 1 windows before it recomputes the sum exactly.
    if (updates_since_exact_[i] >= kWindowsBetweenExactSums * averaging_factors_[i]) {
      in.fail("modified Allan window slid past its exact recomputation");
    }
  }
}

}  // namespace allan
}  // namespace imu_lab
