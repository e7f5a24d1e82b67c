#include "imu_lab/emulator/analytic_profile_avar.h"

#include "imu_lab/noise/analytic_avar.h"
#include "imu_lab/noise/make_noise_process.h"

namespace imu_lab {
namespace emulator {

double analytic_axis_avar(const TriadErrorModel& triad, int axis, double tau_s, double tau0_s) {
  double avar = 0.0;
  for (const auto& parameters : triad.noise_per_axis.at(axis)) {
    // Built exactly as the emulator builds it (bandwidth included); the seed is irrelevant
    // because only the process's expected AVAR is read.
    const auto process = noise::make_noise_process(parameters, /*stream_seed=*/0, triad.bandwidth_hz);
    avar += process->allan_variance(tau_s, tau0_s);
  }
  if (triad.pulse_weight > 0.0) avar += noise::pulse_quantization_avar(triad.pulse_weight, tau_s);
  if (triad.output_lsb[axis] > 0.0) avar += noise::output_quantization_avar(triad.output_lsb[axis], tau_s, tau0_s);
  return avar;
}

}  // namespace emulator
}  // namespace imu_lab
