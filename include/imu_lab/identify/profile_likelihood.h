// One-sided profile bound of a term's amplitude: the amplitude at which the best fit with that
// amplitude held fixed (all other parameters free) has a GMM distance larger than the best fit's
// by chi2_1(2 confidence - 1) (e.g. 2.71 for 95 %): the distance plays the role of -2 log L.
#pragma once

#include <vector>

#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/fit_problem.h"
#include "imu_lab/identify/model_structure.h"

namespace imu_lab {
namespace identify {

// Bisections of the bracket (one doubling of the amplitude) a bound gets: 2^(1/128), under 1 %
// in amplitude. The bracket's upper end is reported, so a bound errs on the safe side.
constexpr int kBoundBisections = 7;

// The one-sigma bound beside it: one-sided at 68.27 % (chi2_1 quantile 0.227), the upper end of
// a 68.3 % interval [0, bound] for a term reported absent or unconstrained; 4 bisections, under
// 5 % in amplitude (the upper end of the bracket again).
constexpr double kOneSigmaConfidence = 0.6827;
constexpr int kOneSigmaBoundBisections = 4;

// slot_index's amplitude bound for the fitted (structure, log_parameters, best_cost). For an
// absent term, first append its slot with a negligible amplitude (append_negligible_slot).
// `bisections` halve the bracket that many times. With `one_sigma_bound`, the one-sigma bound
// is written there.
double profile_upper_bound(const std::vector<FitPoint>& points, const ModelStructure& structure,
                           const std::vector<double>& log_parameters, double best_cost, int slot_index,
                           const DataSpan& span, const MomentWeights& weights, double confidence,
                           double* one_sigma_bound = nullptr, int bisections = kBoundBisections);

// Bound of an absent term whose shape the data would have to choose (Markov, sinusoid,
// resonance): its slot is appended with a free shape at each start (unit-amplitude terms), at
// 1 % of its envelope there, and profiled with the shape free, so the amplitude climbs wherever
// the shape lets it fit best; the largest bound over the starts (to 1 % in amplitude). Only the
// climbs that can still hold the largest bound are bisected; the result is the same.
double shaped_profile_upper_bound(const std::vector<FitPoint>& points, const ModelStructure& structure,
                                  const std::vector<double>& log_parameters, double best_cost,
                                  const std::vector<Term>& start_shapes, const DataSpan& span,
                                  const MomentWeights& weights, double confidence,
                                  double* one_sigma_bound = nullptr);

// Appends `slot` (its shape fixed) with an amplitude far below its envelope, so the fit is
// unchanged. Throws std::invalid_argument for a slot with a free shape.
void append_negligible_slot(const std::vector<FitPoint>& points, const TermSlot& slot, ModelStructure* structure,
                            std::vector<double>* log_parameters);

}  // namespace identify
}  // namespace imu_lab
