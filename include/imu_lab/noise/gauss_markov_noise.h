// First-order Gauss-Markov rate noise (q_c, T_c), and its T_c -> infinity limit, the rate random
// walk K. Samples are exact interval averages (IntegratedGaussMarkov), so eq. 5.7 holds down to
// tau0 even for T_c ~ tau0.
#pragma once

#include <limits>

#include "imu_lab/noise/integrated_gauss_markov.h"
#include "imu_lab/noise/noise_process.h"
#include "imu_lab/noise/normal_stream.h"

namespace imu_lab {
namespace noise {

class GaussMarkovNoise : public NoiseProcess {
 public:
  // Markov: starts from its stationary distribution.
  static GaussMarkovNoise markov(double q_c_per_sqrt_s, double correlation_time_s, NormalStream normals);
  // Rate random walk: starts at zero.
  static GaussMarkovNoise random_walk(double density_per_sqrt_s, NormalStream normals);
  // White density N through a first-order low-pass with corner bandwidth_hz: a Markov process
  // with T_c = 1 / (2 pi f_c) and q_c = N / T_c (same PSD, N^2 / (1 + (f / f_c)^2)).
  static GaussMarkovNoise band_limited_white(double density_per_sqrt_hz, double bandwidth_hz, NormalStream normals);

  double next_interval_average(double start_s, double interval_s) override;
  double allan_variance(double tau_s, double tau0_s) const override;
  double sample_variance(double interval_s) const override;
  std::string kind() const override { return kind_; }

 private:
  GaussMarkovNoise(double decay_rate_per_s, double drive_density, NormalStream normals, std::string kind);

  IntegratedGaussMarkov propagator_;
  NormalStream normals_;
  double state_ = 0.0;
  std::string kind_;
};

}  // namespace noise
}  // namespace imu_lab
