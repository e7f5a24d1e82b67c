#include "imu_lab/ros/noise_table.h"

#include <cmath>

#include "imu_lab/common/format_number.h"

namespace imu_lab {
namespace ros_io {
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
    return text;
  }
  if (std::isfinite(amplitude.upper_bound)) {
    return "< " + format_table_number(amplitude.upper_bound * unit.per_si) + " (" +
           identify::term_status_name(term.status) + ")";
  }
  return identify::term_status_name(term.status);
}

}  // namespace

identify::UnitScale display_unit(identify::SensorKind sensor, identify::TermKind kind) {
  const auto units = identify::amplitude_units(sensor, kind);
  if (units.empty()) return {"si", 1.0};
  return units.size() > 1 ? units[1] : units[0];
}

std::string format_noise_table(const std::vector<identify::TriadFit>& triads) {
  std::string table;
  char line[256];
  for (const identify::TriadFit& triad : triads) {
    for (int axis = 0; axis < 3; ++axis) {
      for (const identify::TermEstimate& term : triad.axes[axis].terms) {
        const identify::UnitScale unit = display_unit(triad.sensor, term.kind);
        std::snprintf(line, sizeof(line), "  %-8s %-18s %-8s %-22s %s\n",
                      identify::axis_name(triad.sensor, axis).c_str(), term.name.c_str(),
                      identify::amplitude_symbol(term.kind).c_str(), unit.key.c_str(),
                      format_term(term, unit).c_str());
        table += line;
      }
    }
    table += "  worst " + identify::sensor_prefix(triad.sensor) + " axis: " +
             identify::axis_name(triad.sensor, triad.worst_axis) + " (" + triad.worst_axis_reason + ")\n";
  }
  return table;
}

}  // namespace ros_io
}  // namespace imu_lab
