#include "imu_lab/identify/start_values.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "imu_lab/identify/units.h"

namespace imu_lab {
namespace identify {

double envelope_amplitude(const Term& shaped, const std::vector<FitPoint>& points) {
  Term unit = shaped;
  unit.amplitude = 1.0;
  double smallest_ratio = std::numeric_limits<double>::infinity();
  for (const FitPoint& point : points) {
    const double unit_avar = term_avar(unit, point.tau_s);
    if (unit_avar > 0.0) smallest_ratio = std::min(smallest_ratio, point.avar / unit_avar);
  }
  return std::sqrt(smallest_ratio);
}

std::vector<Term> start_shapes(const TermSlot& slot, const std::vector<FitPoint>& points, const DataSpan& span) {
  const double nyquist_hz = 1.0 / (2.0 * span.tau0_s);
  Term base{slot.kind, 1.0, slot.fixed_shape, 0.0};
  if (!slot.shape_free) return {base};
  std::vector<Term> shapes;
  const auto add = [&](double shape, double width) {
    Term term = base;
    term.shape = shape;
    term.width = width;
    shapes.push_back(term);
  };
  switch (slot.kind) {
    case TermKind::kWhiteRate:
      for (double fraction : {0.2, 0.5, 1.0, 2.0}) add(fraction * nyquist_hz, 0.0);
      break;
    case TermKind::kBiasInstability:
      add(nyquist_hz, 0.0);
      add(1.0 / span.tau_min_s, 0.0);
      break;
    case TermKind::kResonance:
      for (const FitPoint& point : points) {
        const double frequency = 0.5 / point.tau_s;
        if (frequency > nyquist_hz || frequency < 0.1 * nyquist_hz) continue;
        for (double relative_width : {0.05, 0.3}) add(frequency, relative_width * frequency);
      }
      break;
    default:
      for (const FitPoint& point : points) {
        if (slot.kind == TermKind::kMarkov) add(point.tau_s / 2.0, 0.0);
        if (slot.kind == TermKind::kSinusoid) {
          const double frequency_hz = std::min(nyquist_hz, 0.371 / point.tau_s);
          if (frequency_hz * span.record_length_s >= kFewestLinePeriods) add(frequency_hz, 0.0);
        }
        if (slot.kind == TermKind::kZeroDcFamily) add(point.tau_s, 0.0);
        if (slot.kind == TermKind::kZeroDcGaussian) add(point.tau_s * point.tau_s, 0.0);
        if (slot.kind == TermKind::kHighPassWhite) add(std::min(nyquist_hz, 1.0 / (2.0 * units::kPi * point.tau_s)), 0.0);
      }
      break;
  }
  return shapes;
}

std::vector<std::vector<double>> new_slot_starts(const TermSlot& slot, const std::vector<FitPoint>& points,
                                                 const DataSpan& span, const std::vector<double>& envelope_fractions) {
  std::vector<std::vector<double>> starts;
  for (const Term& shape : start_shapes(slot, points, span)) {
    const double envelope = envelope_amplitude(shape, points);
    if (!(envelope > 0.0) || !std::isfinite(envelope)) continue;
    for (double fraction : envelope_fractions) {
      std::vector<double> start = {std::log(fraction * envelope)};
      if (slot.shape_free) start.push_back(std::log(shape.shape));
      if (slot.shape_free && slot.kind == TermKind::kResonance) start.push_back(std::log(shape.width / shape.shape));
      starts.push_back(start);
    }
  }
  return starts;
}

}  // namespace identify
}  // namespace imu_lab
