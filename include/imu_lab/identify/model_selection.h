// Stepwise model selection on the GMM distance J (fit_problem.h): forward from the best single
// term, adding the candidate that lowers J most while the fall is significant; then backward,
// dropping any term whose removal does not raise J significantly; an extra term (Markov,
// sinusoid, resonance, zero-DC) that an absent standard term replaces within its threshold is
// swapped for it; repeated while anything changes. Each comparison uses one weight matrix, that of
// the current model (the null hypothesis; recomputed whenever the model changes, scaled to the
// measured curve), so each fall of J is a chi-squared statistic with the added parameters as
// degrees of freedom (the GMM distance test, Newey and West, International Economic Review 1987)
// and holds its size whatever the grid.
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

// A statistic within a factor 2 of its threshold (either side), or on the other side of it from
// the decision (`in_model`: the term is in the selected model): the decision could have gone the
// other way on another record. The other side happens where the selection admitted a term under
// a smaller spread than the one its statistic is reported under (doc/identification.md).
bool is_borderline(double statistic, double threshold, bool in_model);

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

// A rising term (K, R) whose own AVAR exceeds the measured band's upper bound (fit_result.h) at
// a fit point claims more than the curve holds (a K that runs past a curve turning down): the
// index of the first such term of `model`, or -1. The other terms are judged by where they
// dominate, so a partial above the band there is the fit's excursion, named in the warnings
// (on exact curves the band is +-1 %, and a hump or the white floor may graze it).
int term_claiming_more_than_the_curve(const std::vector<FitPoint>& points, const NoiseModel& model,
                                      const MomentWeights& weights);

// Selects from scratch or from `start`; the first weights come from `first_weight_model` (a
// description of the whole curve), then from each accepted model. `covariance` holds the
// points' averaging factors; `discrepancy` is the relative spread added to every point.
SelectedModel select_model(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                           OavarCovariance& covariance, double discrepancy, const NoiseModel& first_weight_model,
                           const SelectedModel* start = nullptr);

// The selected structure refitted under its own weights with another discrepancy (iterated),
// with its removal statistics there.
void refit_selected(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                    OavarCovariance& covariance, double discrepancy, SelectedModel* selected);

// As refit_selected, without the removal statistics (a refit to measure the distance at).
void reweigh_selected(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                      OavarCovariance& covariance, double discrepancy, SelectedModel* selected);

// `base` with `slot` appended, fitted as the selection fits a candidate: from each start shape at
// each of options.envelope_fractions, beside the base terms as they are and halved, the best of
// options.solves_per_candidate solves (ranked by their starting distance).
SolveOutcome fit_with_new_slot(const std::vector<FitPoint>& points, const DataSpan& span, const FitOptions& options,
                               const ModelStructure& base, const std::vector<double>& base_parameters,
                               const TermSlot& slot, const MomentWeights& weights, ModelStructure* extended);

// Refits a fixed structure from `start` and from a few perturbations of it; the best solve.
SolveOutcome refit_structure(const std::vector<FitPoint>& points, const ModelStructure& structure,
                             const std::vector<double>& start, const DataSpan& span, const MomentWeights& weights);

}  // namespace identify
}  // namespace imu_lab
