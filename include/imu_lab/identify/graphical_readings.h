// The readings the standards describe (IEEE Std 952 annex C), labelled for what they are. They
// are correct for a single term and misleading for mixtures (Krobka 2015 section 6), which is why
// the fit is the answer and these are shown beside it with warnings (fit_warnings.h).
#pragma once

#include <limits>
#include <vector>

#include "imu_lab/allan/batch.h"

namespace imu_lab {
namespace identify {

struct GraphicalReadings {
  static constexpr double kNotAvailable = std::numeric_limits<double>::quiet_NaN();
  // Upper bound of N: the slope -1/2 ray through the leftmost point, lowered until it touches
  // the curve (min over points of sigma * sqrt(tau)). A true bound only if no anti-alias filter
  // pulls the leftmost points down.
  double white_rate_upper_bound = kNotAvailable;
  // Slope reading of N: sigma at tau = 1 s (log-log interpolation), NaN outside the curve.
  double white_rate_at_1s = kNotAvailable;
  // Slope reading of K: sigma at tau = 3 s.
  double random_walk_at_3s = kNotAvailable;
  // Flat-tangent reading of B: the minimum deviation / 0.664 (sqrt(2 ln 2 / pi)).
  double minimum_deviation = kNotAvailable;
  double tau_at_minimum_s = kNotAvailable;
  double bias_instability_from_minimum = kNotAvailable;
};

// sqrt(2 ln 2 / pi): the flicker floor of eq. 5.3 is 0.664 B.
constexpr double kFlickerFloorFactor = 0.6642824702679600;

// Reads the curve (all points, in increasing tau). Throws InputError for an empty curve.
GraphicalReadings read_graphically(const std::vector<allan::StabilityPoint>& points);

// Deviation at tau by log-log interpolation between the bracketing points; NaN outside.
double interpolate_deviation(const std::vector<allan::StabilityPoint>& points, double tau_s);

}  // namespace identify
}  // namespace imu_lab
