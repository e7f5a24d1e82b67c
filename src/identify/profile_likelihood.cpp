#include "imu_lab/identify/profile_likelihood.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "imu_lab/identify/chi_squared.h"
#include "imu_lab/identify/start_values.h"

namespace imu_lab {
namespace identify {

namespace {
constexpr double kNegligibleFraction = 1e-4;  // of the envelope: 1e-8 of the AVAR it could reach
}

void append_negligible_slot(const std::vector<FitPoint>& points, const TermSlot& slot, ModelStructure* structure,
                            std::vector<double>* log_parameters) {
  if (slot.shape_free) throw std::invalid_argument("append_negligible_slot: the slot's shape must be fixed");
  const double envelope = envelope_amplitude(Term{slot.kind, 1.0, slot.fixed_shape, 0.0}, points);
  structure->slots.push_back(slot);
  log_parameters->push_back(std::log(kNegligibleFraction * envelope));
}

double profile_upper_bound(const std::vector<FitPoint>& points, const ModelStructure& structure,
                           const std::vector<double>& log_parameters, double best_cost, int slot_index,
                           const DataSpan& span, const MomentWeights& weights, double confidence, int bisections) {
  const int amplitude_index = parameter_offset(structure, slot_index);
  // cost = J / 2
  const double critical = 0.5 * chi_squared_quantile(2.0 * confidence - 1.0, 1.0);
  std::vector<double> current = log_parameters;
  const auto excess_at = [&](double log_amplitude) {
    std::vector<double> start = current;
    start[amplitude_index] = log_amplitude;
    const SolveOutcome outcome = solve_model(points, structure, start, span, weights, {amplitude_index});
    if (outcome.usable && outcome.cost < best_cost + critical) current = outcome.log_parameters;
    return outcome.usable ? outcome.cost - best_cost : critical + 1.0;
  };
  double low = log_parameters[amplitude_index];
  double high = low;
  for (int step = 0; step < 80; ++step) {  // bracket: doubling steps up from the estimate
    high = low + std::log(2.0);
    if (excess_at(high) >= critical) break;
    low = high;
  }
  for (int iteration = 0; iteration < bisections; ++iteration) {
    const double middle = 0.5 * (low + high);
    if (excess_at(middle) >= critical) {
      high = middle;
    } else {
      low = middle;
    }
  }
  return std::exp(high);
}

double shaped_profile_upper_bound(const std::vector<FitPoint>& points, const ModelStructure& structure,
                                  const std::vector<double>& log_parameters, double best_cost,
                                  const std::vector<Term>& start_shapes, const DataSpan& span,
                                  const MomentWeights& weights, double confidence) {
  constexpr double kStartFraction = 0.01;  // of the envelope: 1e-4 of the AVAR it could reach
  constexpr int kBisections = 7;           // 2^(1/128): under 1 % in amplitude
  double bound = std::numeric_limits<double>::quiet_NaN();
  for (const Term& shape : start_shapes) {
    const double envelope = envelope_amplitude(shape, points);
    if (!(envelope > 0.0) || !std::isfinite(envelope)) continue;
    ModelStructure extended = structure;
    extended.slots.push_back({shape.kind, true, 0.0});
    std::vector<double> start = log_parameters;
    start.push_back(std::log(kStartFraction * envelope));
    start.push_back(std::log(shape.shape));
    if (shape.kind == TermKind::kResonance) start.push_back(std::log(shape.width / shape.shape));
    const double at_start =
        profile_upper_bound(points, extended, start, best_cost, static_cast<int>(extended.slots.size()) - 1, span,
                            weights, confidence, kBisections);
    if (!(at_start <= bound)) bound = at_start;
  }
  return bound;
}

}  // namespace identify
}  // namespace imu_lab
