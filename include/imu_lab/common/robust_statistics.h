// Robust location and scale for the detectors that look for rests and plateaus in a recording
// (a minority of moving windows must not move the estimates).
#pragma once

#include <vector>

namespace imu_lab {

// Element n/2 of the sorted values (the median for an odd count, the upper median for an even
// one). Requires at least one value.
double upper_median(std::vector<double> values);

// The sigma of one of two independent, equally noisy Gaussian values, from the absolute
// differences of such pairs: median |d| = 0.6745 sqrt(2) sigma, so sigma = 1.4826 median |d| / sqrt(2).
double sigma_from_absolute_differences(std::vector<double> absolute_differences);

// E[min(z^2, c^2)] for a standard normal z: a mean square of values clipped at c scales divided
// by it is a consistent variance (0.99501 at c = 3), blind to the outliers the clip cuts.
double clipped_gaussian_second_moment(double c);

}  // namespace imu_lab
