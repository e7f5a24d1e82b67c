// White rate noise N (angle / velocity random walk): the interval average has variance N^2 / h.
#pragma once

#include "imu_lab/noise/noise_process.h"
#include "imu_lab/noise/normal_stream.h"

namespace imu_lab {
namespace noise {

class WhiteRateNoise : public NoiseProcess {
 public:
  WhiteRateNoise(double density_per_sqrt_hz, NormalStream normals);
  double next_interval_average(double start_s, double interval_s) override;
  double allan_variance(double tau_s, double tau0_s) const override;
  double sample_variance(double interval_s) const override;
  std::string kind() const override { return "white_rate"; }

 private:
  double density_;
  NormalStream normals_;
};

}  // namespace noise
}  // namespace imu_lab
