// Which terms a candidate model has and how its parameters are laid out for the optimiser:
// every parameter positive, so the optimiser works on logarithms (ln amplitude, then ln shape
// when the shape is free, then ln relative width for a resonance). A bias instability whose
// cutoff is fixed, or a white rate without a front end, has no shape parameter.
#pragma once

#include <vector>

#include "imu_lab/identify/noise_model.h"

namespace imu_lab {
namespace identify {

struct TermSlot {
  TermKind kind = TermKind::kWhiteRate;
  bool shape_free = false;
  double fixed_shape = 0.0;  // used when the kind has a shape and it is not free
  // Resonances fit their width relative to their natural frequency (width / f_n), so a bound on
  // the damping is a box; the slot carries it whenever it carries a shape.
};

struct ModelStructure {
  std::vector<TermSlot> slots;
  double output_quantization_density = 0.0;  // see NoiseModel
};

int slot_parameter_count(const TermSlot& slot);
int parameter_count(const ModelStructure& structure);
// Index of slot i's ln-amplitude in the parameter vector (its ln-shapes, if free, follow).
int parameter_offset(const ModelStructure& structure, int slot_index);

NoiseModel model_from_log_parameters(const ModelStructure& structure, const std::vector<double>& log_parameters);
// One slot's term from its slot_parameter_count(slot) ln-parameters.
Term term_from_log_parameters(const TermSlot& slot, const double* log_parameters);
// Inverse of model_from_log_parameters for a model whose terms match the structure's slots.
std::vector<double> log_parameters_from_model(const ModelStructure& structure, const NoiseModel& model);

// The same slots in the same order (kinds, free shapes, fixed shapes); parameters aside.
bool same_structure(const ModelStructure& a, const ModelStructure& b);

// The structure and parameters without slot i.
void remove_slot(ModelStructure& structure, std::vector<double>& log_parameters, int slot_index);

// Reorders slots (and their parameters) by term_order_less(), so term names are stable.
void canonical_order(ModelStructure& structure, std::vector<double>& log_parameters);

}  // namespace identify
}  // namespace imu_lab
