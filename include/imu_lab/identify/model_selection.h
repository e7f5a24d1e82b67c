// Stepwise model selection by likelihood ratio: forward from the best single term, adding the
// candidate that improves the likelihood most while the improvement is significant; then
// backward, dropping any term whose removal does not worsen the fit significantly; an extra term
// (Markov, sinusoid, zero-DC) that a standard term can replace within its threshold is swapped
// for it; repeated while anything changes. Absent terms therefore come out absent instead of
// being forced to a small, meaningless value.
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
  std::string action;  // "start", "add", "remove", "swap <extra term> for"
  std::string term;    // kind name
  double lr_statistic = 0.0;  // 2 (log L_larger - log L_smaller)
  double threshold = 0.0;     // chi2 quantile it was compared with
};

struct SelectedModel {
  ModelStructure structure;  // canonical order
  std::vector<double> log_parameters;
  double cost = 0.0;
  // Per slot: 2 delta log L of removing it from the final model (its significance).
  std::vector<double> removal_lr_statistics;
  std::vector<SelectionStep> steps;
};

// Every slot the options allow (Markov slots repeated max_markov_terms times).
std::vector<TermSlot> candidate_slots(const FitOptions& options, const DataSpan& span);

SolverSettings solver_settings(const FitOptions& options);

// The chi2 quantile (1 - significance, its parameter count) a likelihood-ratio statistic must
// exceed for one slot to enter or stay. A term with a free shape was searched over one start per point,
// so its statistic is the best of ~point_count tries: Bonferroni, significance / point_count
// (without it a long Markov term wins on the few-EDF last points and displaces K).
double slot_lr_threshold(const FitOptions& options, const TermSlot& slot, int point_count);

SelectedModel select_model(const std::vector<FitPoint>& points, const DataSpan& span,
                           const FitOptions& options);

// Refits a fixed structure from `start` and from a few perturbations of it; the best solve.
SolveOutcome refit_structure(const std::vector<FitPoint>& points, const ModelStructure& structure,
                             const std::vector<double>& start, const DataSpan& span,
                             const SolverSettings& settings);

}  // namespace identify
}  // namespace imu_lab
