// Turns one channel's pooled streaming sums into Stable32-style points: deviation, term count,
// noise type, EDF (summed over segments, each at its own length) and chi-squared bounds, using
// the batch reference's EDF and bounds.
#pragma once

#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/streaming_channel.h"

namespace imu_lab {
namespace allan {

struct PointUnits {
  double tau0_s = 0.0;
  // Multiplies a deviation in accumulated units into rate units: 1 for rates, 1 / tau0 for increments.
  double value_scale = 1.0;
  double confidence = 0.683;
};

// One point per planned averaging factor that has at least one term, ascending m.
std::vector<StabilityPoint> streaming_points(Statistic statistic, const ChannelAccumulator& channel,
                                             const PointUnits& units);

}  // namespace allan
}  // namespace imu_lab
