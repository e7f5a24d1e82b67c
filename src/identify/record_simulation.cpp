#include "imu_lab/identify/record_simulation.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "imu_lab/noise/make_noise_process.h"
#include "imu_lab/noise/normal_stream.h"

namespace imu_lab {
namespace identify {

std::vector<noise::ProcessParameters> emulator_processes(const NoiseModel& model, double tau0_s,
                                                         double record_length_s) {
  std::vector<noise::ProcessParameters> processes;
  for (const Term& term : model.terms) {
    switch (term.kind) {
      case TermKind::kWhiteAngle: processes.push_back(noise::WhiteAngleParameters{term.amplitude, 0.0}); break;
      case TermKind::kWhiteRate:
        if (term.shape > 0.0) {  // behind the front end: exactly a Markov process
          const double time_constant_s = 1.0 / (2.0 * 3.14159265358979323846 * term.shape);
          processes.push_back(noise::MarkovParameters{term.amplitude / time_constant_s, time_constant_s});
        } else {
          processes.push_back(noise::WhiteRateParameters{term.amplitude});
        }
        break;
      case TermKind::kBiasInstability:
        processes.push_back(noise::BiasInstabilityParameters{term.amplitude, term.shape,
                                                             std::max(1.0 / term.shape, tau0_s), record_length_s});
        break;
      case TermKind::kRandomWalk: processes.push_back(noise::RandomWalkParameters{term.amplitude}); break;
      case TermKind::kRateRamp: processes.push_back(noise::RateRampParameters{term.amplitude}); break;
      case TermKind::kMarkov:
        processes.push_back(noise::MarkovParameters{term.amplitude / term.shape, term.shape});
        break;
      case TermKind::kSinusoid: processes.push_back(noise::SinusoidParameters{term.amplitude, term.shape, 0.0}); break;
      case TermKind::kZeroDcFamily:
        processes.push_back(noise::ZeroDcFamilyParameters{2, term.amplitude * term.amplitude, term.shape});
        break;
      case TermKind::kResonance:
        processes.push_back(noise::ResonanceParameters{term.amplitude, term.shape, term.width});
        break;
      case TermKind::kZeroDcGaussian:
        processes.push_back(noise::ZeroDcGaussianParameters{2, term.amplitude * term.amplitude, term.shape});
        break;
      case TermKind::kHighPassWhite:
        processes.push_back(noise::HighPassWhiteParameters{term.amplitude, term.shape});
        break;
    }
  }
  // The output's rounding, as the white noise it adds.
  if (model.output_quantization_density > 0.0) {
    processes.push_back(noise::WhiteRateParameters{model.output_quantization_density});
  }
  return processes;
}

std::vector<double> simulate_rates(const NoiseModel& model, double tau0_s, long long sample_count, std::uint64_t seed) {
  const auto parameters = emulator_processes(model, tau0_s, sample_count * tau0_s);
  std::vector<std::unique_ptr<noise::NoiseProcess>> processes;
  for (size_t i = 0; i < parameters.size(); ++i) {
    const std::string stream = "identify.bootstrap." + noise::process_kind(parameters[i]) + "#" + std::to_string(i);
    processes.push_back(noise::make_noise_process(parameters[i], noise::stream_seed(seed, stream)));
  }
  std::vector<double> rates(sample_count, 0.0);
  for (long long k = 0; k < sample_count; ++k) {
    for (auto& process : processes) rates[k] += process->next_interval_average(k * tau0_s, tau0_s);
  }
  return rates;
}

}  // namespace identify
}  // namespace imu_lab
