#include "imu_lab/noise/gauss_markov_noise.h"

#include <cmath>
#include <utility>

namespace imu_lab {
namespace noise {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}

GaussMarkovNoise::GaussMarkovNoise(double decay_rate_per_s, double drive_density, NormalStream normals,
                                   std::string kind)
    : propagator_(decay_rate_per_s, drive_density), normals_(normals), kind_(std::move(kind)) {
  if (decay_rate_per_s > 0.0) state_ = std::sqrt(propagator_.stationary_variance()) * normals_.next();
}

GaussMarkovNoise GaussMarkovNoise::markov(double q_c, double correlation_time_s, NormalStream normals) {
  return GaussMarkovNoise(1.0 / correlation_time_s, q_c, normals, "markov");
}

GaussMarkovNoise GaussMarkovNoise::random_walk(double density, NormalStream normals) {
  return GaussMarkovNoise(0.0, density, normals, "random_walk");
}

GaussMarkovNoise GaussMarkovNoise::band_limited_white(double density, double bandwidth_hz, NormalStream normals) {
  const double decay_rate = kTwoPi * bandwidth_hz;
  return GaussMarkovNoise(decay_rate, density * decay_rate, normals, "band_limited_white_rate");
}

double GaussMarkovNoise::next_interval_average(double, double interval_s) {
  const double n1 = normals_.next();
  const double n2 = normals_.next();
  return propagator_.advance(state_, interval_s, n1, n2) / interval_s;
}

double GaussMarkovNoise::allan_variance(double tau_s, double) const {
  // Eq. 5.7 in the form q^2 tau g3(lambda tau); lambda = 0 gives K^2 tau / 3.
  const double q = propagator_.drive_density();
  return q * q * tau_s * integrated_markov_factor(propagator_.decay_rate_per_s() * tau_s);
}

double GaussMarkovNoise::sample_variance(double interval_s) const {
  return propagator_.stationary_average_variance(interval_s);
}

}  // namespace noise
}  // namespace imu_lab
