// A lot: M units of one model, each characterised by its own noise report (the noise.yaml that
// `allan` writes). Per unit the identified terms; across units, per channel and term, a
// datasheet-style summary in the field's units (the unit the noise table prints: deg/sqrt(h),
// deg/h, micro-g, m/s/sqrt(h), ...): typical = the median over the units that identify the term,
// worst = the largest of them, and their sample standard deviation (n - 1) with its chi-squared
// interval; plus the typical model of each channel (median amplitudes and shapes of the terms a
// majority of units identify) for drawing beside the units' Allan curves. See doc/lot.md.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "imu_lab/identify/noise_model.h"
#include "imu_lab/repeatability/repeatability.h"

namespace imu_lab {
namespace repeatability {

struct LotUnit {
  std::string name;
  // identify::read_noise_report_values of the unit's noise report.
  std::map<std::string, double> report_values;
};

struct UnitTermValue {
  std::string unit;
  double value = 0.0, sigma = 0.0;  // sigma NaN where the report gives none (an unconstrained term)
};

// One term of one channel across the lot, in the field's unit.
struct LotTerm {
  std::string channel, term;              // "gyro_x", "bias_instability"
  std::string parameter;                  // symbol and field unit as in the report's keys, e.g. "B_deg_h"
  std::string field_unit;                 // its unit part, e.g. "deg_h"
  std::vector<UnitTermValue> identified;  // the units whose report gives a value, in unit order
  std::vector<std::string> absent_units;  // the others
  double absent_upper_bound_max = 0.0;    // largest upper bound those reports give (NaN: none)
  double typical = 0.0;                   // median of the identified values (NaN: none)
  double worst = 0.0;                     // largest identified value (NaN: none)
  SpreadEstimate spread;                  // over the identified values (count < 2: not estimated)
};

struct LotSummary {
  std::vector<std::string> units;
  double confidence = 0.95;
  std::vector<LotTerm> terms;  // by channel, then in the order of TermKind, then by name
};

// Throws std::invalid_argument for fewer than 2 units, a unit without any term, or duplicate names.
LotSummary lot_summary(const std::vector<LotUnit>& units, double confidence);

// The typical noise model of a channel: every term identified by at least half of the units,
// with the median of their SI amplitudes and shapes (a white rate term's shape is its front-end
// corner), and the median output quantization.
identify::NoiseModel typical_model(const std::vector<LotUnit>& units, const std::string& channel);

// tau_s, then per channel <channel>_typical_dev_<unit> (the typical model's Allan deviation).
std::string typical_model_csv(const std::vector<LotUnit>& units, const std::vector<double>& taus_s);

// One row per channel, term and unit (value, sigma), then the term's typical, worst and spread
// rows (CSV); the same as YAML with the intervals; a Markdown page with the datasheet table.
std::string lot_csv(const LotSummary& summary);
std::string lot_yaml(const LotSummary& summary);
std::string lot_markdown(const LotSummary& summary);

}  // namespace repeatability
}  // namespace imu_lab
