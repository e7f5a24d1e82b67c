#include "imu_lab/pipeline/noise_table.h"

#include <cmath>

#include "imu_lab/common/format_number.h"

namespace imu_lab {
namespace pipeline {
namespace {

// Four significant digits: this table is read by people; the YAML keeps full precision.
std::string format_table_number(double value) { return format_number(value, 4); }

std::string format_term(const identify::TermEstimate& term, const identify::UnitScale& unit) {
  const auto& amplitude = term.amplitude;
  if (term.status == identify::TermStatus::kPresent && std::isfinite(amplitude.value)) {
    std::string text = format_table_number(amplitude.value * unit.per_si);
    if (std::isfinite(amplitude.sigma)) {
      text += " ± " + format_table_number(amplitude.sigma * unit.per_si) + " (" +
              identify::sigma_source_name(term.sigma_source) + ")";
    }
    // Where other structures were weighed, the 68.3 % interval is their mixture's quantiles: it
    // may sit off-centre, or far inside value ± sigma (doc/identification.md, "Units 4-6").
    if (!amplitude.structure_mixture.empty()) {
      text += ", 68 %: " + format_table_number(amplitude.interval_low(1.0) * unit.per_si) + " to " +
              format_table_number(amplitude.interval_high(1.0) * unit.per_si);
    }
    return text;
  }
  if (std::isfinite(amplitude.upper_bound)) {
    return "< " + format_table_number(amplitude.upper_bound * unit.per_si) + " (" +
           identify::term_status_name(term.status) + ")";
  }
  return identify::term_status_name(term.status);
}

// ", T_c 0.0123 ± 0.002 s", ", f_n 19.8 ± 0.1 Hz, width 1.6 ± 0.3 Hz", ", low-pass 31.2 ± 0.9 Hz":
// the shape of a term in the model with its sigma where one was estimated, so that a line or a
// Markov term reads as what it is and the front end's corner carries its precision.
std::string format_shape(const identify::TermEstimate& term) {
  std::string text;
  const auto append = [&text](const std::string& label, const identify::ParameterEstimate& estimate,
                              const identify::UnitScale& unit) {
    if (!std::isfinite(estimate.value)) return;
    text += ", " + label + " " + format_table_number(estimate.value * unit.per_si);
    if (std::isfinite(estimate.sigma)) text += " ± " + format_table_number(estimate.sigma * unit.per_si);
    text += " " + unit.key;
  };
  if (term.status == identify::TermStatus::kAbsent || !identify::has_shape(term.kind)) return text;
  const auto units = identify::shape_units(term.kind);
  if (units.empty()) return text;
  const std::string label =
      term.kind == identify::TermKind::kWhiteRate ? "low-pass" : identify::shape_symbol(term.kind);
  append(label, term.shape, units.front());
  if (!identify::width_symbol(term.kind).empty()) append(identify::width_symbol(term.kind), term.width, units.front());
  return text;
}

}  // namespace

identify::UnitScale display_unit(identify::SensorKind sensor, identify::TermKind kind) {
  return identify::field_amplitude_unit(sensor, kind);
}

std::string format_noise_table(const std::vector<identify::TriadFit>& triads) {
  std::string table;
  char line[512];
  for (const identify::TriadFit& triad : triads) {
    for (int axis = 0; axis < 3; ++axis) {
      for (const identify::TermEstimate* term : identify::terms_in_report_order(triad.axes[axis])) {
        const identify::UnitScale unit = display_unit(triad.sensor, term->kind);
        std::snprintf(
            line, sizeof(line), "  %-8s %-18s %-8s %-22s %s%s%s\n", identify::axis_name(triad.sensor, axis).c_str(),
            term->name.c_str(), identify::amplitude_symbol(term->kind).c_str(), unit.key.c_str(),
            format_term(*term, unit).c_str(), format_shape(*term).c_str(), term->borderline ? " [borderline]" : "");
        table += line;
      }
      for (const std::string& warning : triad.axes[axis].warnings) {
        table += "  " + identify::axis_name(triad.sensor, axis) + " warning: " + warning + "\n";
      }
    }
    table += "  worst " + identify::sensor_prefix(triad.sensor) +
             " axis: " + identify::axis_name(triad.sensor, triad.worst_axis) + " (" + triad.worst_axis_reason + ")\n";
  }
  return table;
}

}  // namespace pipeline
}  // namespace imu_lab
