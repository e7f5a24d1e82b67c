// Warnings that set the graphical readings against the fit, as seed 003 section 6 describes:
// a slope -1/2 segment that is a Markov flank, a minimum that over-states B, a low-pass filter
// pulling the leftmost points down, and a model that does not describe the data.
#pragma once

#include <string>
#include <vector>

#include "imu_lab/identify/fit_result.h"

namespace imu_lab {
namespace identify {

// Ratio above which a reading is said to disagree with the fit.
constexpr double kReadingDisagreementRatio = 1.5;

std::vector<std::string> fit_warnings(const FitResult& fit);

}  // namespace identify
}  // namespace imu_lab
