// Lag-1 autocorrelation of the rate averaged over non-overlapping blocks of m samples, and of its
// first three differences, from running sums (Riley & Greenhall's noise identification, which the
// batch code runs on the stored series). Per segment, a series w_0..w_{n-1} needs only sum w,
// sum w^2, sum w_i w_{i+1}, w_0 and w_{n-1}; segments are pooled by adding centred sums.
// An update runs over every block mean the ring completed since the last one; four or more in
// a row are summed plainly and folded into the compensated sums once: at most kPhaseBlockPoints
// terms, so < 4.6e-13 relative (the argument of streaming_block_sums.h).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "imu_lab/allan/streaming_block_sums.h"
#include "imu_lab/allan/streaming_compensated_sum.h"
#include "imu_lab/allan/streaming_phase_ring.h"

namespace imu_lab {
namespace allan {

constexpr int kMaxBlockDifferences = 3;  // the Hadamard family differences up to three times

// Pooled over segments, for the d-times differenced block means (d = 0 .. kMaxBlockDifferences).
struct BlockSeriesSummary {
  std::array<double, kMaxBlockDifferences + 1> lag1_numerator{};   // sum (w_i - mean)(w_{i+1} - mean)
  std::array<double, kMaxBlockDifferences + 1> centred_squares{};  // sum (w_i - mean)^2
  std::array<double, kMaxBlockDifferences + 1> raw_squares{};      // sum w_i^2
  std::array<std::int64_t, kMaxBlockDifferences + 1> count{};      // points
};

class BlockMeanAutocorrelation {
 public:
  explicit BlockMeanAutocorrelation(std::vector<int> averaging_factors);

  void start_segment();                // folds the open segment into the pooled sums
  void update(const PhaseRing& ring);  // block means ending up to ring.newest()

  BlockSeriesSummary summary(std::size_t tau_index) const;  // closed segments and the open one
  std::size_t heap_bytes() const;
  void save(BinaryWriter& out) const;
  // processed_count: the level's points already folded in (checks where the next ones resume).
  void load(BinaryReader& in, std::int64_t processed_count);

 private:
  // One update's plain sums for a whole chain: lane d belongs to the d-times differenced series.
  struct ChainPartials {
    LaneVector sum = {};
    LaneVector squares = {};
    LaneVector lag1_products = {};
  };
  static_assert(kMaxBlockDifferences + 1 == BlockSums::kLanes, "one lane per difference order");
  struct SeriesMoments {
    CompensatedSum sum;
    CompensatedSum squares;
    CompensatedSum lag1_products;
    double first = 0.0;
    double last = 0.0;
    std::int64_t count = 0;
    void add(double value);
    double centred_lag1() const;
    double centred_squares() const;
  };
  using Chain = std::array<SeriesMoments, kMaxBlockDifferences + 1>;

  // One block mean, compensated term by term; a segment's first ones start the differenced series.
  static void add_block_mean(double mean, Chain& chain);
  // Once every order has a previous value: `block_count` block means ending at first_end[0],
  // first_end[m], ...; branch-free, the four orders in the lanes of one vector.
  static void add_steady_block_means(const double* first_end, std::int64_t block_count, int m, Chain& chain);
  static void fold(const Chain& segment, BlockSeriesSummary& pooled);

  std::vector<int> averaging_factors_;
  std::vector<Chain> open_;
  std::vector<BlockSeriesSummary> closed_;
  std::vector<std::int64_t> next_block_end_;
};

}  // namespace allan
}  // namespace imu_lab
