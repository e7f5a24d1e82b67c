#include "imu_lab/noise/white_rate_noise.h"

#include <cmath>

#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace noise {

WhiteRateNoise::WhiteRateNoise(double density, NormalStream normals) : density_(density), normals_(normals) {}

double WhiteRateNoise::next_interval_average(double, double interval_s) {
  return density_ / std::sqrt(interval_s) * normals_.next();
}

double WhiteRateNoise::allan_variance(double tau_s, double) const { return white_rate_avar(density_, tau_s); }

double WhiteRateNoise::sample_variance(double interval_s) const { return density_ * density_ / interval_s; }

}  // namespace noise
}  // namespace imu_lab
