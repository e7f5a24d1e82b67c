// One triad's measurement: per axis i, with w the input (the true interval average),
//   r = K(T, dT/dt) * w + c2 .* w.^2 + c3 .* w.^3 + 1e-6 A / 2 .* |w|   (rate-dependent response)
//   r_i = 0 where |r_i| < dead_zone_i
//   output = b_fixed + b_turn_on + b(T, dT/dt) + r + G * specific_force (gyro) + sum of noise
// then optional pulse quantization of the increment, and last the output register's LSB
// (round to nearest). Rates in and out are interval averages. The nonlinear terms are applied to
// the interval average of the input (exact for static and constant-rate inputs only).
// Noise processes are independent except the white rate noise, correlated across the three axes
// by the profile's white_rate_correlation (Cholesky factor on the unit-variance deviates).
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
#include <optional>
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
  std::optional<double> second_temperature_c;  // of the second thermosensor, if the scenario has one
};

class TriadChannel {
 public:
  // triad_name ("gyro", "accelerometer") names the RNG streams, e.g. "gyro.x.markov#1" (the
  // second Markov process on x), each seeded from stream_seed(seed, name).
  TriadChannel(const TriadErrorModel& model, const std::string& triad_name, std::uint64_t seed);

  // Temperature terms (TriadErrorModel::thermal) are evaluated at the interval's mean
  // temperature and mean rate: the polynomial's curvature over one sample is neglected.
  Eigen::Vector3d measure(const Eigen::Vector3d& true_average, const Eigen::Vector3d& specific_force_average,
                          double elapsed_start_s, double interval_s, const SensorTemperature& temperature);
  // At the reference temperature, steady (no temperature terms).
  Eigen::Vector3d measure(const Eigen::Vector3d& true_average, const Eigen::Vector3d& specific_force_average,
                          double elapsed_start_s, double interval_s);

  // The rate-dependent response r above, dead zone included (no bias, no noise).
  Eigen::Vector3d response(const Eigen::Vector3d& true_average, const Eigen::Vector3d& thermal_scale) const;
  // Per-axis variance of one sample's stationary noise (see EmulatedSample); the LSB adds LSB^2 / 12.
  Eigen::Vector3d sample_variance(double interval_s) const;
  // b_fixed + the run-to-run bias drawn for this run.
  Eigen::Vector3d total_bias() const { return model_.bias_fixed + turn_on_bias_; }
  const Eigen::Matrix3d& scale_misalignment_matrix() const { return scale_misalignment_; }
  const std::vector<std::unique_ptr<noise::NoiseProcess>>& processes(int axis) const { return processes_[axis]; }

 private:
  TriadErrorModel model_;
  Eigen::Matrix3d scale_misalignment_;
  Eigen::Vector3d turn_on_bias_;
  std::array<std::vector<std::unique_ptr<noise::NoiseProcess>>, 3> processes_;
  std::array<noise::PulseQuantizer, 3> quantizers_;
  // Cross-axis white rate noise: the index of each axis's white process (-1: none), its density,
  // and the Cholesky factor of white_rate_correlation; correlate_white_ false for identity.
  bool correlate_white_ = false;
  std::array<int, 3> white_index_{-1, -1, -1};
  Eigen::Vector3d white_density_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d white_factor_ = Eigen::Matrix3d::Identity();
};

// Rate samples (interval averages) of the three axes of a triad at rest at the reference
// temperature: round(duration_s x rate_hz) samples from a TriadChannel(model, triad_name, seed).
std::array<std::vector<double>, 3> rates_at_rest(const TriadErrorModel& model, const std::string& triad_name,
                                                 double rate_hz, double duration_s, std::uint64_t seed);

}  // namespace emulator
}  // namespace imu_lab
