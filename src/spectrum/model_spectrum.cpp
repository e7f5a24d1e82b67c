#include "imu_lab/spectrum/model_spectrum.h"

#include <algorithm>
#include <cmath>

#include "imu_lab/noise/analytic_psd.h"

namespace imu_lab {
namespace spectrum {

std::size_t line_bin(const PowerSpectrum& spectrum, double frequency_hz, double tau0_s) {
  const double sample_rate_hz = 1.0 / tau0_s;
  double folded_hz = std::fmod(std::abs(frequency_hz), sample_rate_hz);
  if (folded_hz > 0.5 * sample_rate_hz) folded_hz = sample_rate_hz - folded_hz;
  const auto bin = static_cast<std::size_t>(std::lround(folded_hz / spectrum.resolution_hz));
  return std::min(bin, spectrum.density.size() - 1);
}

std::vector<double> model_density(const identify::NoiseModel& model, const PowerSpectrum& spectrum, double tau0_s) {
  std::vector<double> density(spectrum.density.size(), 0.0);
  for (std::size_t bin = 1; bin < density.size(); ++bin) {
    const bool nyquist = 2 * bin == spectrum.segment_length;  // a real bin: not doubled (welch.cpp)
    density[bin] = (nyquist ? 1.0 : 2.0) * identify::sampled_model_psd(model, spectrum.frequency_hz[bin], tau0_s);
  }
  for (const identify::Term& term : model.terms) {
    if (term.kind != identify::TermKind::kSinusoid) continue;
    const double sampled_amplitude = term.amplitude * noise::interval_average_gain(term.shape, tau0_s);
    // Both lines, +-f0, fold onto one bin of the one-sided estimate.
    const double power = 2.0 * noise::sinusoid_line_power(sampled_amplitude);
    const std::size_t bin = line_bin(spectrum, term.shape, tau0_s);
    if (bin > 0) density[bin] += power / spectrum.equivalent_noise_bandwidth_hz;
  }
  return density;
}

}  // namespace spectrum
}  // namespace imu_lab
