#include "imu_lab/identify/profile_likelihood.h"

#include <algorithm>
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

namespace {

// One profile climb: the amplitude at slot_index raised from its start value in doubling steps
// until the distance exceeds the best fit's by the critical value, then the last doubling
// bisected. Each evaluation starts from the last one that stayed below the critical value.
// The one-sigma bound's critical value rides along: its bracket is the doubling step that first
// crosses it.
class ProfileClimb {
 public:
  ProfileClimb(const std::vector<FitPoint>& points, const ModelStructure& structure,
               const std::vector<double>& log_parameters, double best_cost, int slot_index, const DataSpan& span,
               const MomentWeights& weights, double confidence)
      : points_(points),
        structure_(structure),
        span_(span),
        weights_(weights),
        best_cost_(best_cost),
        // cost = J / 2
        critical_(0.5 * chi_squared_quantile(2.0 * confidence - 1.0, 1.0)),
        one_sigma_critical_(0.5 * chi_squared_quantile(2.0 * kOneSigmaConfidence - 1.0, 1.0)),
        amplitude_index_(parameter_offset(structure, slot_index)),
        current_(log_parameters),
        low_(log_parameters[amplitude_index_]),
        high_(low_),
        one_sigma_low_(low_),
        one_sigma_high_(low_) {}

  // Doubling steps up from the start until the critical value is crossed (at most 80).
  void bracket() {
    bool one_sigma_crossed = false;
    for (int step = 0; step < 80; ++step) {
      high_ = low_ + std::log(2.0);
      const double excess = excess_at(high_, one_sigma_crossed ? critical_ : one_sigma_critical_);
      if (!one_sigma_crossed && excess >= one_sigma_critical_) {
        one_sigma_crossed = true;
        one_sigma_low_ = low_;
        one_sigma_high_ = high_;
      }
      if (excess >= critical_) break;
      low_ = high_;
    }
    if (!one_sigma_crossed) one_sigma_low_ = low_, one_sigma_high_ = high_;
  }
  void bisect() { bisect_bracket(critical_, &low_, &high_); }
  void bisect_one_sigma() { bisect_bracket(one_sigma_critical_, &one_sigma_low_, &one_sigma_high_); }
  // The bound lies in (low, high]; high is reported.
  double low() const { return low_; }
  double high() const { return high_; }
  double one_sigma_low() const { return one_sigma_low_; }
  double one_sigma_high() const { return one_sigma_high_; }

 private:
  // The distance's excess over the best fit at an amplitude, exact at or above `decisive` (the
  // critical value the caller compares with); below it, the first iterate found under it.
  double excess_at(double log_amplitude, double decisive) {
    std::vector<double> start = current_;
    start[amplitude_index_] = log_amplitude;
    const SolveOutcome outcome =
        solve_model(points_, structure_, start, span_, weights_, {amplitude_index_}, best_cost_ + decisive);
    if (outcome.usable && outcome.cost < best_cost_ + critical_) current_ = outcome.log_parameters;
    return outcome.usable ? outcome.cost - best_cost_ : critical_ + 1.0;
  }

  void bisect_bracket(double critical, double* low, double* high) {
    const double middle = 0.5 * (*low + *high);
    if (excess_at(middle, critical) >= critical) {
      *high = middle;
    } else {
      *low = middle;
    }
  }

  const std::vector<FitPoint>& points_;
  ModelStructure structure_;
  const DataSpan& span_;
  const MomentWeights& weights_;
  double best_cost_;
  double critical_;
  double one_sigma_critical_;
  int amplitude_index_;
  std::vector<double> current_;
  double low_;
  double high_;
  double one_sigma_low_;
  double one_sigma_high_;
};

// The largest bound over the climbs, bisecting only those that can still hold it: a climb whose
// bracket ends at or below another's lower end cannot (its bound <= its high <= the other's low <
// the other's bound), so the result equals bisecting every climb, at a fraction of the solves.
template <typename Low, typename High, typename Bisect>
double largest_bound(std::vector<ProfileClimb>& climbs, int bisections, Low low, High high, Bisect bisect) {
  std::vector<ProfileClimb*> contenders;
  for (ProfileClimb& climb : climbs) contenders.push_back(&climb);
  const auto drop_outclassed = [&] {
    double highest_low = -std::numeric_limits<double>::infinity();
    for (const ProfileClimb* climb : contenders) highest_low = std::max(highest_low, low(*climb));
    contenders.erase(std::remove_if(contenders.begin(), contenders.end(),
                                    [&](const ProfileClimb* climb) { return high(*climb) <= highest_low; }),
                     contenders.end());
  };
  for (int iteration = 0; iteration < bisections; ++iteration) {
    drop_outclassed();
    for (ProfileClimb* climb : contenders) bisect(*climb);
  }
  double bound = -std::numeric_limits<double>::infinity();
  for (const ProfileClimb* climb : contenders) bound = std::max(bound, high(*climb));
  return std::exp(bound);
}

}  // namespace

double profile_upper_bound(const std::vector<FitPoint>& points, const ModelStructure& structure,
                           const std::vector<double>& log_parameters, double best_cost, int slot_index,
                           const DataSpan& span, const MomentWeights& weights, double confidence,
                           double* one_sigma_bound, int bisections) {
  ProfileClimb climb(points, structure, log_parameters, best_cost, slot_index, span, weights, confidence);
  climb.bracket();
  for (int iteration = 0; iteration < bisections; ++iteration) climb.bisect();
  if (one_sigma_bound != nullptr) {
    for (int iteration = 0; iteration < kOneSigmaBoundBisections; ++iteration) climb.bisect_one_sigma();
    *one_sigma_bound = std::exp(climb.one_sigma_high());
  }
  return std::exp(climb.high());
}

double shaped_profile_upper_bound(const std::vector<FitPoint>& points, const ModelStructure& structure,
                                  const std::vector<double>& log_parameters, double best_cost,
                                  const std::vector<Term>& start_shapes, const DataSpan& span,
                                  const MomentWeights& weights, double confidence, double* one_sigma_bound) {
  constexpr double kStartFraction = 0.01;  // of the envelope: 1e-4 of the AVAR it could reach
  std::vector<ProfileClimb> climbs;
  for (const Term& shape : start_shapes) {
    const double envelope = envelope_amplitude(shape, points);
    if (!(envelope > 0.0) || !std::isfinite(envelope)) continue;
    ModelStructure extended = structure;
    extended.slots.push_back({shape.kind, true, 0.0});
    std::vector<double> start = log_parameters;
    start.push_back(std::log(kStartFraction * envelope));
    start.push_back(std::log(shape.shape));
    if (shape.kind == TermKind::kResonance) start.push_back(std::log(shape.width / shape.shape));
    climbs.emplace_back(points, extended, start, best_cost, static_cast<int>(extended.slots.size()) - 1, span, weights,
                        confidence);
    climbs.back().bracket();
  }
  if (climbs.empty()) {
    if (one_sigma_bound != nullptr) *one_sigma_bound = std::numeric_limits<double>::quiet_NaN();
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double bound = largest_bound(
      climbs, kBoundBisections, [](const ProfileClimb& climb) { return climb.low(); },
      [](const ProfileClimb& climb) { return climb.high(); }, [](ProfileClimb& climb) { climb.bisect(); });
  if (one_sigma_bound != nullptr) {
    *one_sigma_bound = largest_bound(
        climbs, kOneSigmaBoundBisections, [](const ProfileClimb& climb) { return climb.one_sigma_low(); },
        [](const ProfileClimb& climb) { return climb.one_sigma_high(); },
        [](ProfileClimb& climb) { climb.bisect_one_sigma(); });
  }
  return bound;
}

}  // namespace identify
}  // namespace imu_lab
