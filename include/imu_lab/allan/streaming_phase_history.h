// The whole phase of a segment, but only while it is short: Stable32's noise-type rule falls back
// from the lag-1 autocorrelation (streamable from sums) to the B1 ratio at taus with fewer than
// kMinimumLag1Points block means, and B1 as the batch code evaluates it needs the series itself
// (at a shorter tau, with MVAR/AVAR). Those taus only exist on levels whose segment holds at most
// kMinimumLag1Points * m_exact + 1 points, so the history keeps the finest such level: when it
// outgrows its capacity it drops every other point (rate averaged over twice as many samples) and
// moves up one level. Memory: two buffers (the open segment and the longest closed one) of
// capacity points each, per channel.
#pragma once

#include <cstdint>
#include <vector>

#include "imu_lab/allan/checkpoint_codec.h"

namespace imu_lab {
namespace allan {

class PhaseHistory {
 public:
  explicit PhaseHistory(std::size_t capacity);

  void push(double level0_phase);  // every level-0 phase point of the open segment, from its 0
  void start_segment();            // keeps the longer of the open and the longest closed segment

  // The phase at `level` (as ResolutionLevel holds it) of the longest segment so far, the open
  // one included; empty when that segment is held only at a coarser level.
  std::vector<double> phase_at_level(int level) const;

  std::int64_t open_segment_count() const { return open_.level0_count; }  // level-0 points pushed
  std::size_t heap_bytes() const;
  void save(BinaryWriter& out) const;
  void load(BinaryReader& in);

 private:
  struct Segment {
    int level = 0;
    std::int64_t level0_count = 0;  // level-0 points pushed
    std::vector<double> phase;      // points 0, 2^level, 2 * 2^level, ... divided by 2^level
  };
  void append(Segment& segment, double level0_phase) const;
  static void save_segment(const Segment& segment, BinaryWriter& out);
  void load_segment(Segment& segment, BinaryReader& in) const;

  std::size_t capacity_;
  Segment open_;
  Segment longest_closed_;
};

}  // namespace allan
}  // namespace imu_lab
