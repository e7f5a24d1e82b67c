// The fit's per-window table (observed and fitted delta bias, residual) as CSV, for
// scripts/plot_thermal.py. Columns: triad, axis, unit, stamp_s, temperature_c, rate_c_s,
// orientation, observed_delta_bias, fitted_delta_bias, residual (values in `unit`, SI).
#pragma once

#include <string>

#include "imu_lab/thermal/thermal_fit.h"

namespace imu_lab {
namespace thermal {

void write_thermal_residual_csv(const std::string& path, const ThermalFitResult& result);  // atomic

}  // namespace thermal
}  // namespace imu_lab
