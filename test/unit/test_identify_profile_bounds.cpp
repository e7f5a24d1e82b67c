// The bound of an absent shaped term (profile_likelihood.h): the largest of the profile climbs
// from its start shapes. Only the climbs that can still hold the largest are bisected; the
// result must equal climbing and bisecting every start on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "identify_test_records.h"
#include "imu_lab/identify/fit.h"
#include "imu_lab/identify/profile_likelihood.h"
#include "imu_lab/identify/start_values.h"

namespace imu_lab {
namespace identify {
namespace {

// Each start's own bound: its slot appended with a free shape at 1 % of its envelope, profiled
// with every bisection (what shaped_profile_upper_bound did start by start).
std::vector<double> bounds_start_by_start(const FitResult& fit, const std::vector<Term>& shapes, double best_cost) {
  std::vector<double> bounds;
  for (const Term& shape : shapes) {
    const double envelope = envelope_amplitude(shape, fit.points);
    ModelStructure extended = fit.structure;
    extended.slots.push_back({shape.kind, true, 0.0});
    std::vector<double> start = fit.log_parameters;
    start.push_back(std::log(0.01 * envelope));
    start.push_back(std::log(shape.shape));
    if (shape.kind == TermKind::kResonance) start.push_back(std::log(shape.width / shape.shape));
    bounds.push_back(profile_upper_bound(fit.points, extended, start, best_cost,
                                         static_cast<int>(extended.slots.size()) - 1, fit.span, fit.weights,
                                         fit.options.upper_bound_confidence));
  }
  return bounds;
}

TEST(IdentifyProfileBounds, ShapedBoundEqualsTheLargestStartByStartBound) {
  // White noise and a rate random walk, 100 Hz, 20 min: no Markov term, line or mode.
  const double rate_hz = 100.0, duration_s = 1200.0;
  const std::vector<double> rates = identify_test::emulate_axis_rates(
      {noise::WhiteRateParameters{1e-3}, noise::RandomWalkParameters{2e-5}}, rate_hz, duration_s, 20261202);
  const FitResult fit = fit_noise_model(identify_test::octave_oadev(rates, rate_hz), 1.0 / rate_hz, duration_s);
  const double best_cost = 0.5 * fit.quality.distance;
  bool starts_disagree = false;
  for (TermKind kind : {TermKind::kMarkov, TermKind::kSinusoid, TermKind::kResonance}) {
    for (const Term& term : fit.model.terms) ASSERT_NE(term.kind, kind) << term_kind_name(kind) << " should be absent";
    // Four starts spread over the candidates, as the fit takes them.
    const std::vector<Term> all = start_shapes({kind, true, 0.0}, fit.points, fit.span);
    ASSERT_GE(all.size(), 4u);
    std::vector<Term> shapes;
    for (size_t i = 0; i < 4; ++i) shapes.push_back(all[i * (all.size() - 1) / 3]);
    const std::vector<double> each = bounds_start_by_start(fit, shapes, best_cost);
    const double largest = *std::max_element(each.begin(), each.end());
    const double smallest = *std::min_element(each.begin(), each.end());
    starts_disagree |= smallest < 0.9 * largest;
    const double shaped = shaped_profile_upper_bound(fit.points, fit.structure, fit.log_parameters, best_cost, shapes,
                                                     fit.span, fit.weights, fit.options.upper_bound_confidence);
    EXPECT_DOUBLE_EQ(shaped, largest) << term_kind_name(kind);
  }
  // Some kind's starts disagree, so choosing among the climbs matters.
  EXPECT_TRUE(starts_disagree);
}

// The one-sigma bound rides along the 95 % climb: below it, and where the profile's distance has
// risen by the chi2_1 quantile at 2 x 0.6827 - 1 (0.227), to its 4 bisections (2^(1/16) in amplitude).
TEST(IdentifyProfileBounds, OneSigmaBoundIsWhereTheDistanceRisesByItsQuantile) {
  const double rate_hz = 100.0, duration_s = 1200.0;
  const std::vector<double> rates = identify_test::emulate_axis_rates(
      {noise::WhiteRateParameters{1e-3}, noise::RandomWalkParameters{2e-5}}, rate_hz, duration_s, 20261203);
  const FitResult fit = fit_noise_model(identify_test::octave_oadev(rates, rate_hz), 1.0 / rate_hz, duration_s);
  const TermEstimate* ramp = fit.find("rate_ramp");
  ASSERT_NE(ramp, nullptr);
  ASSERT_EQ(ramp->status, TermStatus::kAbsent);
  EXPECT_LT(ramp->amplitude.upper_bound_one_sigma, ramp->amplitude.upper_bound);

  ModelStructure structure = fit.structure;
  std::vector<double> log_parameters = fit.log_parameters;
  append_negligible_slot(fit.points, {TermKind::kRateRamp, false, 0.0}, &structure, &log_parameters);
  const double best_cost = 0.5 * fit.quality.distance;
  const int ramp_index = parameter_offset(structure, static_cast<int>(structure.slots.size()) - 1);
  const auto distance_rise = [&](double amplitude) {
    std::vector<double> start = log_parameters;
    start[ramp_index] = std::log(amplitude);
    const SolveOutcome outcome = solve_model(fit.points, structure, start, fit.span, fit.weights, {ramp_index});
    EXPECT_TRUE(outcome.usable);
    return 2.0 * (outcome.cost - best_cost);
  };
  const double quantile = 0.2267;  // chi2_1 at 0.3654
  const double bound = ramp->amplitude.upper_bound_one_sigma;
  EXPECT_GT(distance_rise(bound), quantile * 0.98) << "bound " << bound;
  EXPECT_LT(distance_rise(bound * std::pow(2.0, -1.0 / 16.0)), quantile * 1.02) << "bound " << bound;
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
