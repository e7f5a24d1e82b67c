#include "imu_lab/identify/graphical_readings.h"

#include <cmath>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace identify {

double interpolate_deviation(const std::vector<allan::StabilityPoint>& points, double tau_s) {
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const auto& a = points[i];
    const auto& b = points[i + 1];
    if (tau_s < a.tau_s || tau_s > b.tau_s || !(a.deviation > 0.0) || !(b.deviation > 0.0)) {
      continue;
    }
    const double weight = std::log(tau_s / a.tau_s) / std::log(b.tau_s / a.tau_s);
    return std::exp((1.0 - weight) * std::log(a.deviation) + weight * std::log(b.deviation));
  }
  if (points.size() == 1 && points[0].tau_s == tau_s) return points[0].deviation;
  return GraphicalReadings::kNotAvailable;
}

GraphicalReadings read_graphically(const std::vector<allan::StabilityPoint>& points) {
  GraphicalReadings readings;
  for (const auto& point : points) {
    if (!(point.deviation > 0.0) || !(point.tau_s > 0.0)) continue;
    const double ray = point.deviation * std::sqrt(point.tau_s);
    if (!(ray >= readings.white_rate_upper_bound)) readings.white_rate_upper_bound = ray;
    if (!(point.deviation >= readings.minimum_deviation)) {
      readings.minimum_deviation = point.deviation;
      readings.tau_at_minimum_s = point.tau_s;
    }
  }
  if (std::isnan(readings.minimum_deviation)) {
    throw InputError("graphical readings: the stability curve has no positive point");
  }
  readings.bias_instability_from_minimum = readings.minimum_deviation / kFlickerFloorFactor;
  readings.white_rate_at_1s = interpolate_deviation(points, 1.0);
  readings.random_walk_at_3s = interpolate_deviation(points, 3.0);
  return readings;
}

}  // namespace identify
}  // namespace imu_lab
