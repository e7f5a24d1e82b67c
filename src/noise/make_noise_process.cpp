#include "imu_lab/noise/make_noise_process.h"

#include <stdexcept>
#include <type_traits>

#include "imu_lab/noise/deterministic_noise.h"
#include "imu_lab/noise/flicker_bank.h"
#include "imu_lab/noise/gauss_markov_noise.h"
#include "imu_lab/noise/resonance_noise.h"
#include "imu_lab/noise/white_angle_noise.h"
#include "imu_lab/noise/white_rate_noise.h"
#include "imu_lab/noise/zero_dc_noise.h"

namespace imu_lab {
namespace noise {

std::string process_kind(const ProcessParameters& parameters) {
  static const char* const kNames[] = {"white_rate", "bias_instability", "random_walk",     "rate_ramp",
                                       "markov",     "sinusoid",         "white_angle",     "zero_dc_family",
                                       "resonance",  "high_pass_white",  "zero_dc_gaussian"};
  static_assert(std::variant_size_v<ProcessParameters> == sizeof(kNames) / sizeof(kNames[0]),
                "one name per parameter type");
  return kNames[parameters.index()];
}

std::unique_ptr<NoiseProcess> make_noise_process(const ProcessParameters& parameters, std::uint64_t seed,
                                                 double bandwidth_hz) {
  NormalStream normals(seed);
  return std::visit(
      [&](const auto& p) -> std::unique_ptr<NoiseProcess> {
        using T = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<T, WhiteRateParameters>) {
          if (bandwidth_hz > 0.0) {
            return std::make_unique<GaussMarkovNoise>(
                GaussMarkovNoise::band_limited_white(p.density_per_sqrt_hz, bandwidth_hz, normals));
          }
          return std::make_unique<WhiteRateNoise>(p.density_per_sqrt_hz, normals);
        } else if constexpr (std::is_same_v<T, BiasInstabilityParameters>) {
          return std::make_unique<FlickerBankNoise>(p, normals);
        } else if constexpr (std::is_same_v<T, RandomWalkParameters>) {
          return std::make_unique<GaussMarkovNoise>(GaussMarkovNoise::random_walk(p.density_per_sqrt_s, normals));
        } else if constexpr (std::is_same_v<T, RateRampParameters>) {
          return std::make_unique<RateRampNoise>(p);
        } else if constexpr (std::is_same_v<T, MarkovParameters>) {
          return std::make_unique<GaussMarkovNoise>(
              GaussMarkovNoise::markov(p.q_c_per_sqrt_s, p.correlation_time_s, normals));
        } else if constexpr (std::is_same_v<T, SinusoidParameters>) {
          return std::make_unique<SinusoidNoise>(p);
        } else if constexpr (std::is_same_v<T, WhiteAngleParameters>) {
          return std::make_unique<WhiteAngleNoise>(p, normals);
        } else if constexpr (std::is_same_v<T, ZeroDcFamilyParameters> || std::is_same_v<T, ZeroDcGaussianParameters>) {
          return std::make_unique<ZeroDcNoise>(p, normals);
        } else if constexpr (std::is_same_v<T, ResonanceParameters>) {
          return std::make_unique<ResonanceNoise>(p, normals);
        } else {
          static_assert(std::is_same_v<T, HighPassWhiteParameters>, "every parameter type is built");
          return std::make_unique<HighPassWhiteNoise>(p, normals);
        }
      },
      parameters);
}

}  // namespace noise
}  // namespace imu_lab
