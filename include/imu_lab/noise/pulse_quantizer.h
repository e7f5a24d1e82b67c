// Physical quantization of a rate-integrating sensor: the cumulative increment is emitted in
// whole pulses of weight S, the remainder carried to the next sample. The rounding error is
// white with Q = S / sqrt(12) only while other noise moves the angle by several pulses per
// sample (doc/models.md).
#pragma once

namespace imu_lab {
namespace noise {

class PulseQuantizer {
 public:
  explicit PulseQuantizer(double pulse_weight) : pulse_weight_(pulse_weight) {}
  // Takes the exact increment of one sample, returns the emitted increment (whole pulses).
  double quantize(double increment);
  double pulse_weight() const { return pulse_weight_; }

 private:
  double pulse_weight_;
  double carry_ = 0.0;  // increment not yet emitted, in [0, S)
};

}  // namespace noise
}  // namespace imu_lab
