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

double ModifiedAccumulator::exact_window_sum(const PhaseRing& ring, int m) const {
  const std::int64_t newest = ring.newest();
  double sum = 0.0;
  for (std::int64_t end = newest - m + 1; end <= newest; ++end) sum += phase_difference(ring, end, m, 2);
  return sum;
}

void ModifiedAccumulator::update(const PhaseRing& ring) {
  const std::int64_t newest = ring.newest();
  for (std::size_t i = 0; i < averaging_factors_.size(); ++i) {
    const int m = averaging_factors_[i];
    if (newest < 2 * static_cast<std::int64_t>(m)) break;  // no second difference yet
    double& window = window_sums_[i];
    window += phase_difference(ring, newest, m, 2);
    if (newest >= 3 * static_cast<std::int64_t>(m)) window -= phase_difference(ring, newest - m, m, 2);
    if (newest < 3 * static_cast<std::int64_t>(m) - 1) continue;  // window not yet m long
    if (++updates_since_exact_[i] >= kWindowsBetweenExactSums * m) {
      window = exact_window_sum(ring, m);
      updates_since_exact_[i] = 0;
    }
    terms_[i].add(window);
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
  window_sums_ = in.get_f64s();
  updates_since_exact_ = in.get_i64s();
  if (window_sums_.size() != averaging_factors_.size() || updates_since_exact_.size() != averaging_factors_.size()) {
    in.fail("modified Allan window count");
  }
}

}  // namespace allan
}  // namespace imu_lab
