// Deterministic rate errors, integrated exactly over each interval: the rate ramp R t and the
// sinusoid Omega0 sin(2 pi f0 t + phase). t is the time since the emulator's start.
#pragma once

#include "imu_lab/noise/noise_process.h"
#include "imu_lab/noise/process_parameters.h"

namespace imu_lab {
namespace noise {

class RateRampNoise : public NoiseProcess {
 public:
  explicit RateRampNoise(const RateRampParameters& parameters) : slope_(parameters.slope_per_s) {}
  double next_interval_average(double start_s, double interval_s) override;
  double allan_variance(double tau_s, double tau0_s) const override;
  double sample_variance(double) const override { return 0.0; }
  std::string kind() const override { return "rate_ramp"; }

 private:
  double slope_;
};

class SinusoidNoise : public NoiseProcess {
 public:
  explicit SinusoidNoise(const SinusoidParameters& parameters) : parameters_(parameters) {}
  double next_interval_average(double start_s, double interval_s) override;
  double allan_variance(double tau_s, double tau0_s) const override;
  double sample_variance(double) const override { return 0.0; }
  std::string kind() const override { return "sinusoid"; }

 private:
  SinusoidParameters parameters_;
};

}  // namespace noise
}  // namespace imu_lab
