// The AVAR points the likelihood uses. Neighbouring overlapping-Allan points are strongly
// correlated (DESIGN.md section 5); points an octave or more apart are nearly independent, so the
// fit keeps one point per octave and treats them as independent chi-squared variates.
#pragma once

#include <vector>

#include "imu_lab/allan/batch.h"

namespace imu_lab {
namespace identify {

struct FitPoint {
  double tau_s = 0.0;
  double avar = 0.0;  // measured overlapping Allan variance
  double edf = 0.0;   // its equivalent degrees of freedom
};

// Keeps, in increasing tau, each usable point (finite, deviation > 0, edf > 0) whose tau is at
// least `min_ratio` times the last kept one (default: octaves, with slack for rounding).
// Throws InputError (common/config_error.h) naming the problem when fewer than 3 points remain
// or taus are not increasing.
std::vector<FitPoint> select_octave_points(const std::vector<allan::StabilityPoint>& points,
                                           double min_ratio = 1.99);

// Octave averaging factors 1, 2, 4, ... up to the largest the overlapping Allan variance can
// evaluate for sample_count samples (2 m <= sample_count - 1 phase steps).
std::vector<int> octave_averaging_factors(long long sample_count);

}  // namespace identify
}  // namespace imu_lab
