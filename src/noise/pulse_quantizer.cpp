#include "imu_lab/noise/pulse_quantizer.h"

#include <cmath>

namespace imu_lab {
namespace noise {

double PulseQuantizer::quantize(double increment) {
  if (pulse_weight_ <= 0.0) return increment;
  const double accumulated = carry_ + increment;
  const double pulses = std::floor(accumulated / pulse_weight_);
  carry_ = accumulated - pulses * pulse_weight_;
  return pulses * pulse_weight_;
}

}  // namespace noise
}  // namespace imu_lab
