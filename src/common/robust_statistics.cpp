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

}  // namespace imu_lab
