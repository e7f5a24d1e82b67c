// An identified noise model (identify/noise_model.h, e.g. read from the `allan` tool's noise.yaml)
// drawn on a Welch estimate (welch.h) of the same channel, in the estimate's convention (one-sided,
// u^2/Hz), so the two can be compared bin by bin (doc/spectrum.md, "The model over the estimate"):
//  - the stochastic terms: 2 S_d(f), S_d the two-sided PSD of the interval-averaged samples
//    (identify::sampled_model_psd: the sensor's averaging and the aliases included);
//  - each sinusoid, which has no density: the power of the sampled line, (Omega0 sinc(pi f0
//    tau0))^2 / 2, over the window's equivalent noise bandwidth, in the bin nearest the line
//    (folded into 0 .. Nyquist). That is what the estimate reads there when the line sits at a
//    bin centre; between two bins Hann reads up to 1.42 dB less (Harris 1978), and its main lobe
//    spreads the line over the neighbouring bins too;
//  - a rate ramp: left out, being deterministic with no stationary PSD (each segment's mean is
//    removed but not its slope, so a strong ramp raises the lowest bins of the estimate).
#pragma once

#include <vector>

#include "imu_lab/identify/noise_model.h"
#include "imu_lab/spectrum/welch.h"

namespace imu_lab {
namespace spectrum {

// One value per bin of `spectrum` (0 at DC, which the estimate leaves empty).
std::vector<double> model_density(const identify::NoiseModel& model, const PowerSpectrum& spectrum, double tau0_s);

// The bin of `spectrum` a line at frequency_hz (any, folded by the sampling) lands nearest.
std::size_t line_bin(const PowerSpectrum& spectrum, double frequency_hz, double tau0_s);

}  // namespace spectrum
}  // namespace imu_lab
