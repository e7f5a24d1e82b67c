// Stepwise model selection on the GMM distance J (fit_problem.h): forward from the best single
// term, adding the candidate that lowers J most while the fall is significant; then backward,
// dropping any term whose removal does not raise J significantly; an extra term (Markov,
// sinusoid, resonance, zero-DC) that an absent standard term replaces within its threshold is
// swapped for it; repeated while anything changes. Every comparison within a selection uses one
// weight matrix, so each fall of J is a chi-squared statistic with the added parameters as
// degrees of freedom (the GMM distance test, Newey and West, International Economic Review 1987)
// and holds its size whatever the grid. The weights come from a model that already describes the
// whole curve (the caller's previous round), never from the small model being grown: a model far
// below the data at some tau would claim a precision there that the data do not have.
#pragma once

#include <string>
#include <vector>

#include "imu_lab/identify/fit_options.h"
#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/fit_problem.h"
#include "imu_lab/identify/model_structure.h"

namespace imu_lab {
namespace identify {

struct SelectionStep {
  std::string action;         // "start", "add", "remove", "swap <extra term> for", "front end"
  std::string term;           // kind name
  double lr_statistic = 0.0;  // fall of J
  double threshold = 0.0;     // chi2 quantile it was compared with
};

// A statistic within a factor 2 of its threshold (either side): the decision could have gone
// the other way on another record.
bool is_borderline(double statistic, double threshold);

struct SelectedModel {
  ModelStructure structure;  // canonical order
  std::vector<double> log_parameters;
  double cost = 0.0;  // J / 2 under `weights`
  MomentWeights weights;
  // Per slot: the rise of J when it is removed from the final model, and its threshold.
  std::vector<double> removal_lr_statistics;
  std::vector<double> removal_thresholds;
  std::vector<SelectionStep> steps;
};

// Every slot the options allow (numbered kinds repeated up to their maximum count).
std::vector<TermSlot> candidate_slots(const FitOptions& options, const DataSpan& span);

// The chi2 quantile (1 - significance, its parameter count) a statistic must exceed for one
// slot to enter or stay. A term with a free shape was searched over one start per point, so its
// statistic is the best of ~point_count tries: Bonferroni, significance / point_count.
double slot_lr_threshold(const FitOptions& options, const TermSlot& slot, int point_count);

// Selects under fixed weights (every comparison then uses the same distance), from scratch or
// from `start` (a selection made under other weights).
SelectedModel select_model(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                           const MomentWeights& weights, double output_quantization_density,
                           const SelectedModel* start = nullptr);

// Iterated GMM for the selected structure: the weights follow the model and the model the
// weights until the model's AVAR at every point moves by less than 5 %; then each term's removal
// statistic under the settled weights. `covariance` holds the points' averaging factors.
void settle_weights(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                    OavarCovariance& covariance, double discrepancy, SelectedModel* selected);

// Refits a fixed structure from `start` and from a few perturbations of it; the best solve.
SolveOutcome refit_structure(const std::vector<FitPoint>& points, const ModelStructure& structure,
                             const std::vector<double>& start, const DataSpan& span, const MomentWeights& weights);

}  // namespace identify
}  // namespace imu_lab
