// The Allan variance a profile promises for one axis: the sum of its independent noise
// processes' analytic AVARs (doc/models.md; independent processes add in AVAR).
#pragma once

#include "imu_lab/emulator/sensor_profile.h"

namespace imu_lab {
namespace emulator {

// tau0_s is needed for the bandwidth-defined terms (white angle noise given as a density). The
// anti-alias filter is included exactly where the emulator applies it (on the white rate noise).
// The output LSB adds LSB^2 tau0 / (12 tau) (white rounding noise, while the other noise spans
// several LSBs). Biases (fixed and turn-on) are constant and have no AVAR; cross-axis
// correlation does not change one axis's AVAR.
double analytic_axis_avar(const TriadErrorModel& triad, int axis, double tau_s, double tau0_s);

}  // namespace emulator
}  // namespace imu_lab
