#include "imu_lab/noise/white_angle_noise.h"

#include <cmath>

#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace noise {

WhiteAngleNoise::WhiteAngleNoise(const WhiteAngleParameters& parameters, NormalStream normals)
    : parameters_(parameters), normals_(normals) {}

double WhiteAngleNoise::per_sample_sigma(double interval_s) const {
  return parameters_.density_per_sqrt_hz > 0.0 ? parameters_.density_per_sqrt_hz / std::sqrt(interval_s)
                                               : parameters_.per_sample_sigma;
}

double WhiteAngleNoise::next_interval_average(double, double interval_s) {
  const double sigma = per_sample_sigma(interval_s);
  if (!started_) {  // the error already present at the first interval's start
    previous_error_ = sigma * normals_.next();
    started_ = true;
  }
  const double error = sigma * normals_.next();
  const double average = (error - previous_error_) / interval_s;
  previous_error_ = error;
  return average;
}

double WhiteAngleNoise::allan_variance(double tau_s, double tau0_s) const {
  return white_angle_avar(per_sample_sigma(tau0_s), tau_s);
}

double WhiteAngleNoise::sample_variance(double interval_s) const {
  const double sigma = per_sample_sigma(interval_s);
  return 2.0 * sigma * sigma / (interval_s * interval_s);
}

}  // namespace noise
}  // namespace imu_lab
