// Where the optimiser starts. Every term alone is bounded by the curve: its amplitude cannot
// exceed the largest value whose partial curve stays under every measured point (the standards'
// "slope ray lowered to touch the curve", generalised to any term's shape). Starts take
// fractions of that envelope, over a grid of shapes for the two-parameter terms.
#pragma once

#include <vector>

#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/fit_problem.h"
#include "imu_lab/identify/model_structure.h"

namespace imu_lab {
namespace identify {

// Largest amplitude of a term of this kind and shape whose AVAR stays at or below every point.
double envelope_amplitude(TermKind kind, double shape, const std::vector<FitPoint>& points,
                          double white_rate_corner_hz = 0.0);

// Candidate shapes for starts: Markov T_c = tau_k / 2 and sinusoid f = 0.37 / tau_k for each
// point (where their partial curves peak), the zero-DC beta at each tau; the fixed or default
// shape otherwise.
std::vector<double> start_shapes(const TermSlot& slot, const std::vector<FitPoint>& points,
                                  const DataSpan& span);

// ln-parameters of one new slot for each (shape, envelope fraction) combination.
std::vector<std::vector<double>> new_slot_starts(const TermSlot& slot,
                                                 const std::vector<FitPoint>& points,
                                                 const DataSpan& span,
                                                 double white_rate_corner_hz,
                                                 const std::vector<double>& envelope_fractions);

}  // namespace identify
}  // namespace imu_lab
