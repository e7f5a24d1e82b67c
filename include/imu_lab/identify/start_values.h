// Where the optimiser starts. Every term alone is bounded by the curve: its amplitude cannot
// exceed the largest value whose partial curve stays under every measured point (the standards'
// "slope ray lowered to touch the curve", generalised to any term's shape). Starts take
// fractions of that envelope, over a grid of shapes for the terms that have one.
#pragma once

#include <vector>

#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/fit_problem.h"
#include "imu_lab/identify/model_structure.h"

namespace imu_lab {
namespace identify {

// Largest amplitude of `shaped` (its amplitude ignored) whose AVAR stays at or below every point.
double envelope_amplitude(const Term& shaped, const std::vector<FitPoint>& points);

// Candidate shapes of a free-shaped slot, as unit-amplitude terms: Markov T_c = tau_k / 2 and
// sinusoid f = 0.371 / tau_k at each point (where their partial curves peak), resonances at
// f_n = 0.5 / tau_k with a narrow and a wide peak, a front end's corner at a few fractions of
// the sample rate, the zero-DC beta at each tau; the fixed shape otherwise.
std::vector<Term> start_shapes(const TermSlot& slot, const std::vector<FitPoint>& points, const DataSpan& span);

// ln-parameters of one new slot for each (shape, envelope fraction) combination.
std::vector<std::vector<double>> new_slot_starts(const TermSlot& slot, const std::vector<FitPoint>& points,
                                                 const DataSpan& span, const std::vector<double>& envelope_fractions);

}  // namespace identify
}  // namespace imu_lab
