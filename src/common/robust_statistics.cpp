#include "imu_lab/common/robust_statistics.h"

#include <algorithm>
#include <cmath>

namespace imu_lab {

double upper_median(std::vector<double> values) {
  const auto middle = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

double sigma_from_absolute_differences(std::vector<double> absolute_differences) {
  return 1.4826 * upper_median(std::move(absolute_differences)) / std::sqrt(2.0);
}

double clipped_gaussian_second_moment(double c) {
  const double tail = std::erfc(c / std::sqrt(2.0));  // P(|z| > c)
  const double density = std::exp(-0.5 * c * c) / std::sqrt(2.0 * M_PI);
  return (1.0 - tail) - 2.0 * c * density + c * c * tail;
}

}  // namespace imu_lab
