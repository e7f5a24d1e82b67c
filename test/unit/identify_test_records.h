// Records for the identification tests, made by the emulator (the project's oracle): a
// TriadChannel built from a TriadErrorModel carrying the noise processes on axis x only.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/streaming_tau_plan.h"
#include "imu_lab/emulator/sensor_channel.h"
#include "imu_lab/emulator/sensor_profile.h"
#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/noise_model.h"

namespace imu_lab {
namespace identify_test {

// Rate samples (interval averages) of the three axes of a triad at rest.
inline std::array<std::vector<double>, 3> emulate_triad_rates(const emulator::TriadErrorModel& model, double rate_hz,
                                                              double duration_s, std::uint64_t seed) {
  return emulator::rates_at_rest(model, "gyro", rate_hz, duration_s, seed);
}

// Rate samples of axis x of a gyro triad at rest carrying `noise` on x only.
inline std::vector<double> emulate_axis_rates(const std::vector<noise::ProcessParameters>& noise, double rate_hz,
                                              double duration_s, std::uint64_t seed, double bandwidth_hz = 0.0) {
  emulator::TriadErrorModel model;
  model.noise_per_axis[0] = noise;
  model.bandwidth_hz = bandwidth_hz;
  return emulate_triad_rates(model, rate_hz, duration_s, seed)[0];
}

// Overlapping Allan deviation of the rates at octave averaging factors.
inline std::vector<allan::StabilityPoint> octave_oadev(const std::vector<double>& rates, double rate_hz) {
  return allan::evaluate_frequency(allan::Statistic::kOverlappingAllan, rates, 1.0 / rate_hz,
                                   identify::octave_averaging_factors(rates.size()));
}

// Overlapping Allan deviation of the rates at the allan tool's default grid, round(10^(i / 10)).
// An OAVAR at m needs 2 m + 1 phase points, rates.size() + 1 of them.
inline std::vector<allan::StabilityPoint> default_grid_oadev(const std::vector<double>& rates, double rate_hz) {
  std::vector<int> factors;
  const auto largest = static_cast<std::int64_t>((rates.size() - 1) / 2);
  for (std::int64_t m : allan::logarithmic_averaging_factors(10.0, largest)) factors.push_back(static_cast<int>(m));
  return allan::evaluate_frequency(allan::Statistic::kOverlappingAllan, rates, 1.0 / rate_hz, factors);
}

// A noise-free overlapping-Allan curve of `model` at octave factors for a record of length_s,
// with white-FM-like EDFs (1.5 length / tau).
inline std::vector<allan::StabilityPoint> exact_octave_curve(const identify::NoiseModel& model, double tau0_s,
                                                             double length_s) {
  std::vector<allan::StabilityPoint> points;
  for (int m : identify::octave_averaging_factors(static_cast<long long>(length_s / tau0_s))) {
    allan::StabilityPoint point;
    point.averaging_factor = m;
    point.tau_s = m * tau0_s;
    point.deviation = std::sqrt(identify::model_avar(model, point.tau_s));
    point.edf = 1.5 * length_s / point.tau_s;
    points.push_back(point);
  }
  return points;
}

}  // namespace identify_test
}  // namespace imu_lab
