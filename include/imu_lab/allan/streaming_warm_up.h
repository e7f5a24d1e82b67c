// The first samples of a run, held until tau0 (median stamp interval) and each channel's offset
// (mean of its finite values) can be fixed; they are then replayed through the engine.
#pragma once

#include <cstdint>
#include <vector>

#include "imu_lab/allan/checkpoint_codec.h"

namespace imu_lab {
namespace allan {

class WarmUpBuffer {
 public:
  explicit WarmUpBuffer(std::size_t channel_count) : channel_count_(channel_count) {}

  void add(std::int64_t stamp_ns, const double* values);
  std::size_t sample_count() const { return stamps_ns_.size(); }
  std::int64_t stamp_ns(std::size_t sample) const { return stamps_ns_[sample]; }
  const double* values(std::size_t sample) const { return &values_[sample * channel_count_]; }

  // Median of the positive intervals between consecutive stamps; 0 when there is none.
  std::int64_t median_interval_ns() const;
  // Per channel, the mean of the finite values (0 when a channel has none).
  std::vector<double> finite_means() const;

  void release();  // frees the memory once replayed
  std::size_t heap_bytes() const;
  void save(BinaryWriter& out) const;
  void load(BinaryReader& in);

 private:
  std::size_t channel_count_;
  std::vector<std::int64_t> stamps_ns_;
  std::vector<double> values_;  // sample-major
};

}  // namespace allan
}  // namespace imu_lab
