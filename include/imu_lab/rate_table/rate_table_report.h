// The files of a rate-table scale-factor test (doc/rate_table.md): the estimates with their
// sigmas as YAML (SI and the customary ppm, deg/h, deg/s, units in every key) and one CSV row per
// plateau (times, nominal and input rate, mean output and its sigma, dead or not, residuals).
#pragma once

#include <string>

#include "imu_lab/rate_table/scale_factor_test.h"

namespace imu_lab {
namespace rate_table {

std::string scale_factor_yaml(const ScaleFactorTestResult& result, const std::string& recording_name);
std::string plateau_csv(const ScaleFactorTestResult& result);
// A few lines for the terminal.
std::string scale_factor_summary(const ScaleFactorTestResult& result);

}  // namespace rate_table
}  // namespace imu_lab
