// The AVAR points the estimator uses. Neighbouring overlapping-Allan points are strongly
// correlated; the estimator carries that correlation (avar_covariance.h), so it may use many of
// them, but a grid much denser than ten per decade adds little information and a nearly
// singular covariance. The fit therefore keeps points at least `min_ratio` apart in tau, the
// same set (up to rounding) whatever the grid the curve was computed on.
#pragma once

#include <vector>

#include "imu_lab/allan/batch.h"

namespace imu_lab {
namespace identify {

struct FitPoint {
  double tau_s = 0.0;
  int averaging_factor = 0;           // m = tau / tau0
  double avar = 0.0;                  // measured overlapping Allan variance
  double pooled_term_fraction = 1.0;  // allan::StabilityPoint's: below 1 when pooled over segments
};

// The default spacing of the fit points: a factor sqrt(2) in tau (two per octave).
constexpr double kFitPointRatio = 1.41;
// The ladder of averaging factors round(10^(k / 5)), k = 0, 1, ...: every decade grid of 5, 10,
// 20, 30 ... points per decade holds it, exactly within the engine's exact range.
constexpr double kLadderPointsPerDecade = 5.0;
// How far (relative, in tau) a curve point may lie from a ladder factor and still stand for it.
// Beyond its exact range the streaming engine reports each factor rounded up to a multiple of the
// pyramid block, by less than 2 / exact limit (0.2 % at the default limit 1000;
// allan/streaming_tau_plan.h); a 30-per-decade grid's neighbours lie 8 % apart.
constexpr double kLadderTolerance = 0.03;

// When the curve's grid holds at least 80 % of the ladder up to its largest usable factor (a
// factor counts as held when a curve point lies within kLadderTolerance of it), the usable points
// nearest the ladder's factors: the same points whatever the grid's density, so a denser grid
// changes neither the estimate nor the selection. Otherwise (octaves, hand-picked taus) each
// usable point (finite, deviation > 0, m >= 1) whose tau is at least `min_ratio` times the last
// kept one. Throws InputError (common/config_error.h) naming the problem when fewer than 3
// points remain or taus are not increasing.
std::vector<FitPoint> select_fit_points(const std::vector<allan::StabilityPoint>& points,
                                        double min_ratio = kFitPointRatio);

// Octave averaging factors 1, 2, 4, ... up to the largest the overlapping Allan variance can
// evaluate for sample_count samples (2 m <= sample_count - 1 phase steps).
std::vector<int> octave_averaging_factors(long long sample_count);

}  // namespace identify
}  // namespace imu_lab
