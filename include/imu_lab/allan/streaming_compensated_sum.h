// Compensated summation: the running sums of a 24 h run hold ~1e8 terms, and plain summation
// would lose up to ~1e-8 of relative accuracy on them; carrying each addition's exact rounding
// error (Knuth's branch-free TwoSum, Neumaier's scheme) keeps it near 1e-16.
#pragma once

#include "imu_lab/allan/checkpoint_codec.h"

namespace imu_lab {
namespace allan {

class CompensatedSum {
 public:
  void add(double term) {
    // Branch-free: the sign of running sums of differences is unpredictable.
    const double total = sum_ + term;
    const double term_part = total - sum_;
    compensation_ += (sum_ - (total - term_part)) + (term - term_part);
    sum_ = total;
  }
  double value() const { return sum_ + compensation_; }

  void save(BinaryWriter& out) const {
    out.put_f64(sum_);
    out.put_f64(compensation_);
  }
  void load(BinaryReader& in) {
    sum_ = in.get_finite_f64();
    compensation_ = in.get_finite_f64();
  }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

}  // namespace allan
}  // namespace imu_lab
