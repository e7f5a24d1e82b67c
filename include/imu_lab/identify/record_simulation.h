// Records simulated from an identified model with the emulator's own noise processes
// (noise/make_noise_process.h): the parametric bootstrap's data source.
#pragma once

#include <cstdint>
#include <vector>

#include "imu_lab/identify/noise_model.h"
#include "imu_lab/noise/process_parameters.h"

namespace imu_lab {
namespace identify {

// The emulator's parameter set for each term, and a white one for the output's quantization.
// Bias instability is realised by the emulator's flicker bank over [max(1 / f0, tau0),
// record_length_s]; white noise behind a front end is the Markov process it is exactly.
// Throws std::invalid_argument for a term the emulator cannot generate.
std::vector<noise::ProcessParameters> emulator_processes(const NoiseModel& model, double tau0_s,
                                                         double record_length_s);

// Interval-average rates of one axis, sample_count samples every tau0_s, streams seeded from
// `seed` and each term's name.
std::vector<double> simulate_rates(const NoiseModel& model, double tau0_s, long long sample_count, std::uint64_t seed);

}  // namespace identify
}  // namespace imu_lab
