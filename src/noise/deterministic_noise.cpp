#include "imu_lab/noise/deterministic_noise.h"

#include <cmath>

#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace noise {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}

double RateRampNoise::next_interval_average(double start_s, double interval_s) {
  return slope_ * (start_s + 0.5 * interval_s);  // a linear rate averages to its midpoint
}

double RateRampNoise::allan_variance(double tau_s, double) const { return rate_ramp_avar(slope_, tau_s); }

double SinusoidNoise::next_interval_average(double start_s, double interval_s) {
  // (cos(a) - cos(a + w h)) / (w h) written without the cancellation of the difference.
  const double omega = kTwoPi * parameters_.frequency_hz;
  const double half_angle = 0.5 * omega * interval_s;
  const double mid_phase = omega * (start_s + 0.5 * interval_s) + parameters_.phase_rad;
  const double sinc = half_angle == 0.0 ? 1.0 : std::sin(half_angle) / half_angle;
  return parameters_.amplitude * std::sin(mid_phase) * sinc;
}

double SinusoidNoise::allan_variance(double tau_s, double) const {
  return sinusoid_avar(parameters_.amplitude, parameters_.frequency_hz, tau_s);
}

}  // namespace noise
}  // namespace imu_lab
