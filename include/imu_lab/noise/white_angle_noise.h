// White noise of the integrated quantity (angle / velocity): the sample's increment carries
// e_k - e_{k-1}, e white. Covers the white-angle quantization model (per-sample sigma Q) and
// Krobka 2015's "white noise in angle" (continuous density; per-sample variance density^2 / tau0).
// Bandwidth-defined: its AVAR depends on the sample rate, 3 sigma^2 / tau^2.
#pragma once

#include "imu_lab/noise/noise_process.h"
#include "imu_lab/noise/normal_stream.h"
#include "imu_lab/noise/process_parameters.h"

namespace imu_lab {
namespace noise {

class WhiteAngleNoise : public NoiseProcess {
 public:
  WhiteAngleNoise(const WhiteAngleParameters& parameters, NormalStream normals);
  double next_interval_average(double start_s, double interval_s) override;
  double allan_variance(double tau_s, double tau0_s) const override;
  double sample_variance(double interval_s) const override;
  std::string kind() const override { return "white_angle"; }

  double per_sample_sigma(double interval_s) const;

 private:
  WhiteAngleParameters parameters_;
  NormalStream normals_;
  bool started_ = false;
  double previous_error_ = 0.0;
};

}  // namespace noise
}  // namespace imu_lab
