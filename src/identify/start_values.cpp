#include "imu_lab/identify/start_values.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace imu_lab {
namespace identify {

double envelope_amplitude(TermKind kind, double shape, const std::vector<FitPoint>& points,
                          double white_rate_corner_hz) {
  const Term unit{kind, 1.0, shape};
  double smallest_ratio = std::numeric_limits<double>::infinity();
  for (const FitPoint& point : points) {
    const double unit_avar = term_avar(unit, point.tau_s, white_rate_corner_hz);
    if (unit_avar > 0.0) smallest_ratio = std::min(smallest_ratio, point.avar / unit_avar);
  }
  return std::sqrt(smallest_ratio);
}

std::vector<double> start_shapes(const TermSlot& slot, const std::vector<FitPoint>& points,
                                 const DataSpan& span) {
  if (!slot.shape_free) return {slot.fixed_shape};
  std::vector<double> shapes;
  for (const FitPoint& point : points) {
    switch (slot.kind) {
      case TermKind::kMarkov:
        shapes.push_back(point.tau_s / 2.0);
        break;
      case TermKind::kSinusoid:
        shapes.push_back(0.371 / point.tau_s);
        break;
      case TermKind::kBiasInstability:
        return {1.0 / (2.0 * span.tau0_s), 1.0 / span.tau_min_s};
      default:
        shapes.push_back(point.tau_s);
        break;
    }
  }
  return shapes;
}

std::vector<std::vector<double>> new_slot_starts(const TermSlot& slot,
                                                 const std::vector<FitPoint>& points,
                                                 const DataSpan& span,
                                                 double white_rate_corner_hz,
                                                 const std::vector<double>& envelope_fractions) {
  std::vector<std::vector<double>> starts;
  for (double shape : start_shapes(slot, points, span)) {
    const double envelope = envelope_amplitude(slot.kind, shape, points, white_rate_corner_hz);
    if (!(envelope > 0.0) || !std::isfinite(envelope)) continue;
    for (double fraction : envelope_fractions) {
      std::vector<double> start = {std::log(fraction * envelope)};
      if (slot.shape_free) start.push_back(std::log(shape));
      starts.push_back(start);
    }
  }
  return starts;
}

}  // namespace identify
}  // namespace imu_lab
