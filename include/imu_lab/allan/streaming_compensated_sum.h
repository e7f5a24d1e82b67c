// Neumaier (improved Kahan) summation: the running sums of a 24 h run hold ~1e8 terms, and
// plain summation would lose ~1e-8 of relative accuracy on them; this keeps it near 1e-16.
#pragma once

#include <cmath>

#include "imu_lab/allan/checkpoint_codec.h"

namespace imu_lab {
namespace allan {

class CompensatedSum {
 public:
  void add(double term) {
    const double total = sum_ + term;
    // The smaller operand's low-order bits are what the addition rounded away.
    if (std::abs(sum_) >= std::abs(term)) {
      compensation_ += (sum_ - total) + term;
    } else {
      compensation_ += (term - total) + sum_;
    }
    sum_ = total;
  }
  double value() const { return sum_ + compensation_; }

  void save(BinaryWriter& out) const {
    out.put_f64(sum_);
    out.put_f64(compensation_);
  }
  void load(BinaryReader& in) {
    sum_ = in.get_f64();
    compensation_ = in.get_f64();
  }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

}  // namespace allan
}  // namespace imu_lab
