// One triad's measurement: output = b_fixed + b_turn_on + b(T, dT/dt) + K(T, dT/dt) * input + c .* input.^2
// + G * specific_force (gyro) + sum of noise processes, then optional pulse quantization of the
// increment. Rates in and out are interval averages. The quadratic term is applied to the
// interval average of the input (exact for static and constant-rate inputs only).
// Bandwidth (first-order anti-alias low-pass) is applied exactly to the white rate noise only
// (white -> Gauss-Markov with the same PSD, still exact interval averages). It does not filter
// the truth (a unity-gain low-pass leaves the static truth unchanged; moving scenarios will need
// it), nor the Markov / flicker / random-walk terms (their power above a MEMS corner is
// negligible), nor the white-angle and quantization terms (defined by the sample rate).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "imu_lab/emulator/sensor_profile.h"
#include "imu_lab/noise/noise_process.h"
#include "imu_lab/noise/pulse_quantizer.h"

namespace imu_lab {
namespace emulator {

// The sensor's temperature over the sample interval: mean and mean rate of change.
struct SensorTemperature {
  double temperature_c = 0.0;
  double rate_c_s = 0.0;
};

class TriadChannel {
 public:
  // triad_name ("gyro", "accelerometer") names the RNG streams, e.g. "gyro.x.markov#1" (the
  // second Markov process on x), each seeded from stream_seed(seed, name).
  TriadChannel(const TriadErrorModel& model, const std::string& triad_name, std::uint64_t seed);

  // Temperature terms (TriadErrorModel::thermal) are evaluated at the interval's mean
  // temperature and mean rate: the polynomial's curvature over one sample is neglected.
  Eigen::Vector3d measure(const Eigen::Vector3d& true_average,
                          const Eigen::Vector3d& specific_force_average, double elapsed_start_s,
                          double interval_s, const SensorTemperature& temperature);
  // At the reference temperature, steady (no temperature terms).
  Eigen::Vector3d measure(const Eigen::Vector3d& true_average,
                          const Eigen::Vector3d& specific_force_average, double elapsed_start_s,
                          double interval_s);

  // Per-axis variance of one sample's stationary noise (see ImuSample).
  Eigen::Vector3d sample_variance(double interval_s) const;
  // b_fixed + the run-to-run bias drawn for this run.
  Eigen::Vector3d total_bias() const { return model_.bias_fixed + turn_on_bias_; }
  const Eigen::Matrix3d& scale_misalignment_matrix() const { return scale_misalignment_; }
  const std::vector<std::unique_ptr<noise::NoiseProcess>>& processes(int axis) const {
    return processes_[axis];
  }

 private:
  TriadErrorModel model_;
  Eigen::Matrix3d scale_misalignment_;
  Eigen::Vector3d turn_on_bias_;
  std::array<std::vector<std::unique_ptr<noise::NoiseProcess>>, 3> processes_;
  std::array<noise::PulseQuantizer, 3> quantizers_;
};

}  // namespace emulator
}  // namespace imu_lab
