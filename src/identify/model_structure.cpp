#include "imu_lab/identify/model_structure.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace imu_lab {
namespace identify {

namespace {
// A resonance's free shape is two parameters: f_n and width / f_n.
int free_shape_count(const TermSlot& slot) { return slot.shape_free ? shape_count(slot.kind) : 0; }
}  // namespace

int slot_parameter_count(const TermSlot& slot) { return 1 + free_shape_count(slot); }

int parameter_count(const ModelStructure& structure) {
  return parameter_offset(structure, static_cast<int>(structure.slots.size()));
}

int parameter_offset(const ModelStructure& structure, int slot_index) {
  int offset = 0;
  for (int i = 0; i < slot_index; ++i) offset += slot_parameter_count(structure.slots[i]);
  return offset;
}

NoiseModel model_from_log_parameters(const ModelStructure& structure, const std::vector<double>& log_parameters) {
  if (static_cast<int>(log_parameters.size()) != parameter_count(structure)) {
    throw std::invalid_argument("model_from_log_parameters: parameter count mismatch");
  }
  NoiseModel model;
  model.output_quantization_density = structure.output_quantization_density;
  int index = 0;
  for (const TermSlot& slot : structure.slots) {
    model.terms.push_back(term_from_log_parameters(slot, log_parameters.data() + index));
    index += slot_parameter_count(slot);
  }
  return model;
}

Term term_from_log_parameters(const TermSlot& slot, const double* log_parameters) {
  Term term;
  term.kind = slot.kind;
  term.amplitude = std::exp(log_parameters[0]);
  term.shape = slot.shape_free ? std::exp(log_parameters[1]) : slot.fixed_shape;
  if (free_shape_count(slot) == 2) term.width = term.shape * std::exp(log_parameters[2]);
  return term;
}

std::vector<double> log_parameters_from_model(const ModelStructure& structure, const NoiseModel& model) {
  if (model.terms.size() != structure.slots.size()) {
    throw std::invalid_argument("log_parameters_from_model: term count mismatch");
  }
  std::vector<double> log_parameters;
  for (size_t i = 0; i < structure.slots.size(); ++i) {
    const Term& term = model.terms[i];
    log_parameters.push_back(std::log(term.amplitude));
    if (structure.slots[i].shape_free) log_parameters.push_back(std::log(term.shape));
    if (free_shape_count(structure.slots[i]) == 2) log_parameters.push_back(std::log(term.width / term.shape));
  }
  return log_parameters;
}

bool same_structure(const ModelStructure& a, const ModelStructure& b) {
  if (a.slots.size() != b.slots.size()) return false;
  for (size_t i = 0; i < a.slots.size(); ++i) {
    if (a.slots[i].kind != b.slots[i].kind || a.slots[i].shape_free != b.slots[i].shape_free ||
        a.slots[i].fixed_shape != b.slots[i].fixed_shape) {
      return false;
    }
  }
  return true;
}

void remove_slot(ModelStructure& structure, std::vector<double>& log_parameters, int slot_index) {
  const int offset = parameter_offset(structure, slot_index);
  const int count = slot_parameter_count(structure.slots[slot_index]);
  log_parameters.erase(log_parameters.begin() + offset, log_parameters.begin() + offset + count);
  structure.slots.erase(structure.slots.begin() + slot_index);
}

void canonical_order(ModelStructure& structure, std::vector<double>& log_parameters) {
  const NoiseModel model = model_from_log_parameters(structure, log_parameters);
  std::vector<int> order(structure.slots.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return term_order_less(model.terms[a], model.terms[b]); });
  ModelStructure sorted_structure;
  sorted_structure.output_quantization_density = structure.output_quantization_density;
  std::vector<double> sorted_parameters;
  for (int i : order) {
    sorted_structure.slots.push_back(structure.slots[i]);
    const int offset = parameter_offset(structure, i);
    for (int k = 0; k < slot_parameter_count(structure.slots[i]); ++k) {
      sorted_parameters.push_back(log_parameters[offset + k]);
    }
  }
  structure = sorted_structure;
  log_parameters = sorted_parameters;
}

}  // namespace identify
}  // namespace imu_lab
