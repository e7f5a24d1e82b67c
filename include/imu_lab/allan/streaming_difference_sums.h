// Running sums of one family of phase differences at one averaging factor: enough for the
// variance (mean square) and for Krobka's dispersion (mean square minus squared mean).
#pragma once

#include <cstdint>

#include "imu_lab/allan/streaming_block_sums.h"
#include "imu_lab/allan/streaming_compensated_sum.h"

namespace imu_lab {
namespace allan {

struct DifferenceSums {
  CompensatedSum squares;
  CompensatedSum values;
  std::int64_t count = 0;

  void add(double difference) {
    squares.add(difference * difference);
    values.add(difference);
    ++count;
  }
  void add_block(const BlockSums& block) {
    squares.add(block.squares_total());
    values.add(block.values_total());
    count += block.count;
  }
  void merge(const DifferenceSums& other) {
    squares.add(other.squares.value());
    values.add(other.values.value());
    count += other.count;
  }
  double mean_square() const { return count > 0 ? squares.value() / count : 0.0; }
  double mean() const { return count > 0 ? values.value() / count : 0.0; }

  void save(BinaryWriter& out) const {
    squares.save(out);
    values.save(out);
    out.put_i64(count);
  }
  void load(BinaryReader& in) {
    squares.load(in);
    values.load(in);
    count = in.get_count();
  }
};

}  // namespace allan
}  // namespace imu_lab
