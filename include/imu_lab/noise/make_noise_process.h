// Builds the noise process a parameter set describes, with its own normal-deviate stream.
#pragma once

#include <cstdint>
#include <memory>

#include "imu_lab/noise/noise_process.h"
#include "imu_lab/noise/process_parameters.h"

namespace imu_lab {
namespace noise {

// stream_seed: from noise::stream_seed(user seed, a name unique to this process and axis).
// bandwidth_hz > 0 turns white rate noise into its low-passed (Gauss-Markov) form.
std::unique_ptr<NoiseProcess> make_noise_process(const ProcessParameters& parameters, std::uint64_t stream_seed,
                                                 double bandwidth_hz = 0.0);

}  // namespace noise
}  // namespace imu_lab
