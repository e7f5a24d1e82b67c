// The human-readable report of a calibration: mode and frame, the parameters with their sigmas in
// customary units (ppm, arcsec, deg/h, micro-g), the conditioning, the residuals of every rest and
// move, and the held-out check (the thesis's spread of |g| and |Earth rate|).
#pragma once

#include <string>

#include "imu_lab/calib/bench_calibration.h"

namespace imu_lab {
namespace calib {

std::string calibration_report(const CalibrationResult& result);

}  // namespace calib
}  // namespace imu_lab
