// White rate noise behind a first-order low-pass (an anti-alias filter) is a first-order Markov
// process with q_c T_c = N and T_c = 1 / (2 pi f_c). Once T_c is below twice the shortest tau the
// curve cannot tell the two apart, and a fit splits the white density between N and such a
// Markov term. Their sum in power is the density a filter designer needs (Kalibr's noise_density).
#pragma once

#include "imu_lab/identify/fit_result.h"

namespace imu_lab {
namespace identify {

bool markov_acts_as_low_passed_white(double correlation_time_s, double shortest_tau_s);

// sqrt(N^2 + sum of (q_c T_c)^2 over such Markov terms), present terms only; NaN when there is
// neither. With a known white_rate_corner_hz the model already holds the filter: N alone.
double white_equivalent_density(const FitResult& fit);

}  // namespace identify
}  // namespace imu_lab
