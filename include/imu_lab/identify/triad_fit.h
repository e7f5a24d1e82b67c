// Identification of a triad: each axis fitted on its own, and the worst axis flagged.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/identify/fit.h"
#include "imu_lab/identify/units.h"

namespace imu_lab {
namespace identify {

struct TriadFit {
  SensorKind sensor = SensorKind::kGyroscope;
  std::array<FitResult, 3> axes;  // x, y, z
  // The axis whose fitted deviation, averaged in log over the fitted taus, is largest: the
  // noisiest axis across the whole curve, not at one tau.
  int worst_axis = 0;
  std::string worst_axis_reason;
};

// "gyro_x", ..., "accel_z".
std::string axis_name(SensorKind sensor, int axis);

TriadFit fit_triad(SensorKind sensor, const std::array<std::vector<allan::StabilityPoint>, 3>& curves, double tau0_s,
                   double record_length_s, const FitOptions& options = FitOptions());
// Each axis with its own options (its own output LSB, for one).
TriadFit fit_triad(SensorKind sensor, const std::array<std::vector<allan::StabilityPoint>, 3>& curves, double tau0_s,
                   double record_length_s, const std::array<FitOptions, 3>& options_per_axis);

// Index of the worst axis and why (sets worst_axis, worst_axis_reason).
void flag_worst_axis(TriadFit* triad);

}  // namespace identify
}  // namespace imu_lab
