// The one test every fit applies to its residuals: chi-squared per degree of freedom far above 1
// means the model does not describe the data (a wrong site, an IMU that moved, revisits that do not
// repeat ...), and the tool says so instead of leaving it to a number in a report. "Far" leaves
// room for what a fit's noise estimate misses (random walk over hours: chi2/dof up to about 4 in
// the package's emulated thermal fits) and catches the traps (a calibration fitted at latitude 0
// instead of 50: 32 for a tactical MEMS at 100 Hz, far more for quieter sensors; a hand-turned
// thermal test fitted with one constant per orientation: 1e4 to 2e5). The ring-laser calibration's
// 11 (pulse rounding at rest is a sawtooth, not the white noise the fit assumes) is warned too.
#pragma once

#include <string>

namespace imu_lab {

constexpr double kFarAboveNoiseChi2PerDof = 10.0;  // residuals over 3.2 times the noise

// "" when chi2_per_dof is not far above 1, else "<what>: chi2/dof <x> is far above 1 ...: <causes>".
std::string chi2_warning(const std::string& what, double chi2_per_dof, const std::string& likely_causes);

}  // namespace imu_lab
