// Plain partial sums of one block's terms (a term and its square), in kLanes independent
// accumulators held as one vector (GCC/Clang vector extension: one AVX register, or two SSE2
// ones), so consecutive terms do not wait on each other; the caller folds the block's totals
// into its compensated sums once.
//
// Why plain sums are enough: a block is at most kPhaseBlockPoints = 4096 terms, so each lane
// sums at most n = 1024 of them. Recursive summation of n terms errs by at most
// (n - 1) u sum|t| (Higham, Accuracy and Stability, eq. 4.4; u = 2^-53), i.e. < 1.2e-13 of the
// block's sum of |terms| (exactly its sum for the squares). Folding block totals into a
// CompensatedSum adds only ~u per block, so over any run length the squares keep a relative
// error below ~1.2e-13 and the signed sums an error below 1.2e-13 sum|d|: four orders under the
// 1e-9 the results are held to, with no growth over a 24 h run (the bound is per block, relative).
#pragma once

#include <cstdint>
#include <cstring>

namespace imu_lab {
namespace allan {

// Four doubles operated on lane by lane (exact IEEE per lane, so every instruction set gives
// the same bits).
typedef double LaneVector __attribute__((vector_size(4 * sizeof(double))));

// The block loops (difference and modified accumulators) are compiled twice on x86-64, for
// AVX2 (one instruction per LaneVector operation) and for the baseline (two SSE2 ones), and the
// loader picks one for the CPU: twice the throughput without building for one machine. No FMA
// clone, so both give identical bits. GCC only: clang refuses the baseline clone's LaneVector
// returns (an AVX ABI without AVX) and builds the one baseline loop (the fuzz harnesses).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define IMU_LAB_ALLAN_BLOCK_LOOP __attribute__((target_clones("avx2", "default")))
#else
#define IMU_LAB_ALLAN_BLOCK_LOOP
#endif

// LaneVector values only pass between inlined helpers, never across a call boundary, so GCC's
// note that a 32-byte vector's calling convention differs with and without AVX does not apply.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

// x[0] .. x[3], x unaligned.
inline LaneVector load_lanes(const double* x) {
  LaneVector lanes;
  std::memcpy(&lanes, x, sizeof lanes);
  return lanes;
}

inline LaneVector broadcast_lane(double value) { return LaneVector{value, value, value, value}; }

#pragma GCC diagnostic pop

struct BlockSums {
  static constexpr int kLanes = 4;
  LaneVector squares = {};
  LaneVector values = {};
  std::int64_t count = 0;

  void add(const LaneVector& terms) {
    squares += terms * terms;
    values += terms;
  }
  void add(int lane, double term) {
    squares[lane] += term * term;
    values[lane] += term;
  }
  double squares_total() const { return (squares[0] + squares[1]) + (squares[2] + squares[3]); }
  double values_total() const { return (values[0] + values[1]) + (values[2] + values[3]); }
};

}  // namespace allan
}  // namespace imu_lab
