#include "imu_lab/emulator/analytic_profile_avar.h"

#include <cmath>
#include <type_traits>
#include <variant>

#include "imu_lab/noise/analytic_avar.h"

namespace imu_lab {
namespace emulator {
namespace {

constexpr double kTwoPi = 6.283185307179586;

double process_avar(const noise::ProcessParameters& parameters, double bandwidth_hz, double tau_s, double tau0_s) {
  return std::visit(
      [&](const auto& p) -> double {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, noise::WhiteRateParameters>) {
          if (bandwidth_hz <= 0.0) return noise::white_rate_avar(p.density_per_sqrt_hz, tau_s);
          // White noise through a first-order low-pass is exactly a Gauss-Markov process with
          // T_c = 1 / (2 pi f_c) and the same low-frequency density: q_c T_c = N.
          const double correlation_time_s = 1.0 / (kTwoPi * bandwidth_hz);
          return noise::markov_avar(p.density_per_sqrt_hz / correlation_time_s, correlation_time_s, tau_s);
        } else if constexpr (std::is_same_v<P, noise::BiasInstabilityParameters>) {
          return noise::bias_instability_avar(p.coefficient, p.cutoff_frequency_hz, tau_s);
        } else if constexpr (std::is_same_v<P, noise::RandomWalkParameters>) {
          return noise::random_walk_avar(p.density_per_sqrt_s, tau_s);
        } else if constexpr (std::is_same_v<P, noise::RateRampParameters>) {
          return noise::rate_ramp_avar(p.slope_per_s, tau_s);
        } else if constexpr (std::is_same_v<P, noise::MarkovParameters>) {
          return noise::markov_avar(p.q_c_per_sqrt_s, p.correlation_time_s, tau_s);
        } else if constexpr (std::is_same_v<P, noise::SinusoidParameters>) {
          return noise::sinusoid_avar(p.amplitude, p.frequency_hz, tau_s);
        } else if constexpr (std::is_same_v<P, noise::WhiteAngleParameters>) {
          const double sigma = p.density_per_sqrt_hz > 0.0 ? p.density_per_sqrt_hz / std::sqrt(tau0_s)
                                                           : p.per_sample_sigma;
          return noise::white_angle_avar(sigma, tau_s);
        } else {
          static_assert(std::is_same_v<P, noise::ZeroDcFamilyParameters>, "every process has an AVAR");
          return noise::zero_dc_family_avar(p.exponent_n, p.alpha, p.beta_s, tau_s);
        }
      },
      parameters);
}

}  // namespace

double analytic_axis_avar(const TriadErrorModel& triad, int axis, double tau_s, double tau0_s) {
  double avar = 0.0;
  for (const auto& parameters : triad.noise_per_axis.at(axis)) avar += process_avar(parameters, triad.bandwidth_hz, tau_s, tau0_s);
  if (triad.pulse_weight > 0.0) avar += noise::pulse_quantization_avar(triad.pulse_weight, tau_s);
  return avar;
}

}  // namespace emulator
}  // namespace imu_lab
