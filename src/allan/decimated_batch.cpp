#include "imu_lab/allan/decimated_batch.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace imu_lab {
namespace allan {

std::vector<double> average_rate_blocks(const std::vector<double>& frequency, int level) {
  if (level < 0 || level > 40)
    throw std::invalid_argument("average_rate_blocks: level " + std::to_string(level) + " is outside 0 .. 40");
  const std::size_t block = std::size_t{1} << level;
  std::vector<double> averages(frequency.size() / block);
  for (std::size_t k = 0; k < averages.size(); ++k) {
    double sum = 0.0;
    for (std::size_t i = 0; i < block; ++i) sum += frequency[k * block + i];
    averages[k] = sum / static_cast<double>(block);
  }
  return averages;
}

std::vector<StabilityPoint> evaluate_decimated_frequency(Statistic statistic, const std::vector<double>& frequency,
                                                         double tau0_s, int level,
                                                         const std::vector<int>& level_averaging_factors,
                                                         double confidence) {
  const double block = std::ldexp(1.0, level);
  std::vector<StabilityPoint> points = evaluate_frequency(statistic, average_rate_blocks(frequency, level),
                                                          tau0_s * block, level_averaging_factors, confidence);
  for (StabilityPoint& point : points) point.averaging_factor <<= level;
  return points;
}

}  // namespace allan
}  // namespace imu_lab
