#include "imu_lab/pipeline/noise_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

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

// The IEEE Std 952 terms in the order of their columns.
constexpr identify::TermKind kIeeeKinds[] = {identify::TermKind::kWhiteRate, identify::TermKind::kBiasInstability,
                                             identify::TermKind::kRandomWalk, identify::TermKind::kWhiteAngle,
                                             identify::TermKind::kRateRamp};

bool is_ieee_kind(identify::TermKind kind) {
  for (const identify::TermKind ieee : kIeeeKinds) {
    if (kind == ieee) return true;
  }
  return false;
}

// N, B, K, Q, R for the IEEE terms (the table's column heads), the term's name for the others.
std::string short_name(const std::string& name, identify::TermKind kind) {
  return is_ieee_kind(kind) ? identify::amplitude_symbol(kind) : name;
}

// A value in the sensor's display unit for `kind`, with the unit.
std::string in_display_unit(double value_si, identify::SensorKind sensor, identify::TermKind kind) {
  const identify::UnitScale unit = display_unit(sensor, kind);
  return format_table_number(value_si * unit.per_si) + " " + unit.key;
}

// "2.492 ± 0.0064" (two digits of the sigma are all it is worth), "< 241.1", or "-".
std::string ieee_cell(const identify::TermEstimate* term, const identify::UnitScale& unit) {
  if (term == nullptr) return "-";
  const identify::ParameterEstimate& amplitude = term->amplitude;
  if (term->status == identify::TermStatus::kPresent && std::isfinite(amplitude.value)) {
    std::string cell = format_table_number(amplitude.value * unit.per_si);
    if (std::isfinite(amplitude.sigma)) cell += " ± " + format_number(amplitude.sigma * unit.per_si, 2);
    return cell;
  }
  return std::isfinite(amplitude.upper_bound) ? "< " + format_table_number(amplitude.upper_bound * unit.per_si) : "-";
}

// Breaks a line longer than the console's 120 columns at spaces; continuation lines are indented
// four columns past the line's own indent.
std::string wrapped(const std::string& line) {
  constexpr std::size_t kColumns = 120;
  const std::string indent(line.find_first_not_of(' ') + 4, ' ');
  std::string text;
  std::string rest = line;
  while (rest.size() > kColumns) {
    const std::size_t cut = rest.rfind(' ', kColumns);
    if (cut == std::string::npos || cut <= indent.size()) break;
    text += rest.substr(0, cut) + "\n";
    rest = indent + rest.substr(cut + 1);
  }
  return text + rest + "\n";
}

// What a kind of finding means, in words a user of the numbers needs.
const char* finding_meaning(identify::FindingKind kind) {
  switch (kind) {
    case identify::FindingKind::kSlopeReading:
      return "reading N or K off the curve's slope would over-state it, because other terms carry the curve there";
    case identify::FindingKind::kMarkovAsWhite:
      return "correlated (Markov) noise faster than the curve's first tau acts as white noise; the Kalibr noise "
             "density includes it";
    case identify::FindingKind::kFlatTangentReading:
      return "reading B off the curve's minimum would over-state it, because other terms add to the minimum";
    case identify::FindingKind::kDiscrepancy:
      return "the model follows the measured curve only to within (in AVAR; the sigmas are widened to cover it)";
    case identify::FindingKind::kBandExcursion: return "the fitted curve leaves the measured curve's 95 % band at";
    case identify::FindingKind::kPartialAboveBand:
      return "a term's own curve rises above the measured band (the data do not support its value there)";
    case identify::FindingKind::kOutweighedStructure:
      return "a model with one term more (or one of another kind) fits as well or better, so that term may be there; "
             "the 68 % ranges in noise.yaml lean towards it";
    case identify::FindingKind::kUnconstrained: return "in the model, but the data do not pin it down (use its bound)";
    case identify::FindingKind::kBorderline:
      return "close to the detection threshold: another recording may decide otherwise";
  }
  return "";
}

// The finding as one item of its kind's line, in the table's units.
std::string finding_item(const identify::FitFinding& finding, identify::SensorKind sensor) {
  const std::string symbol = short_name(finding.term, finding.term_kind);
  switch (finding.kind) {
    case identify::FindingKind::kSlopeReading:
    case identify::FindingKind::kFlatTangentReading:
      return symbol + " " + in_display_unit(finding.value, sensor, finding.term_kind) + " at " +
             format_table_number(finding.first_tau_s) + " s, fit " + (finding.fitted_is_bound ? "< " : "") +
             format_table_number(finding.fitted * display_unit(sensor, finding.term_kind).per_si);
    case identify::FindingKind::kDiscrepancy: return format_number(100.0 * finding.value, 2) + " %";
    case identify::FindingKind::kBandExcursion: {
      const bool range = finding.last_tau_s > finding.first_tau_s;
      return format_table_number(finding.first_tau_s) +
             (range ? "-" + format_table_number(finding.last_tau_s) : std::string()) + " s (" +
             format_number(100.0 * std::abs(finding.value), 2) + " % " + (finding.value > 0.0 ? "above" : "below") +
             ")";
    }
    case identify::FindingKind::kPartialAboveBand:
      return symbol + " at " + format_table_number(finding.first_tau_s) + " s";
    case identify::FindingKind::kOutweighedStructure:
      return finding.alternative == finding.term + " added" ? symbol + " added" : finding.alternative;
    case identify::FindingKind::kUnconstrained:
    case identify::FindingKind::kMarkovAsWhite:
    case identify::FindingKind::kBorderline: return symbol;
  }
  return symbol;
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

std::string format_kalibr_lines(const identify::KalibrImuNoise& noise) {
  struct Row {
    const char* key;
    const identify::KalibrValue& value;
    identify::SensorKind sensor;
    const char* unit;
    const char* symbol;
  };
  const Row rows[] = {
      {"gyroscope_noise_density", noise.gyroscope_noise_density, identify::SensorKind::kGyroscope, "rad/s/sqrt(Hz)",
       "N"},
      {"gyroscope_random_walk", noise.gyroscope_random_walk, identify::SensorKind::kGyroscope, "rad/s^2/sqrt(Hz)", "K"},
      {"accelerometer_noise_density", noise.accelerometer_noise_density, identify::SensorKind::kAccelerometer,
       "m/s^2/sqrt(Hz)", "N"},
      {"accelerometer_random_walk", noise.accelerometer_random_walk, identify::SensorKind::kAccelerometer,
       "m/s^3/sqrt(Hz)", "K"},
  };
  std::string text;
  char line[256];
  for (const Row& row : rows) {
    std::snprintf(line, sizeof line, "  %-28s %.4g %s", row.key, row.value.value, row.unit);
    text += line;
    if (row.value.is_upper_bound) {
      text += row.value.value > 0.0 ? std::string(" (an upper bound: ") + row.symbol + " not found on " +
                                          identify::axis_name(row.sensor, row.value.axis) + ")"
                                    : std::string(" (not estimated)");
    }
    text += "\n";
  }
  return text;
}

AxisSummary axis_summary(const identify::TriadFit& triad, int axis) {
  const identify::FitResult& fit = triad.axes[axis];
  AxisSummary summary;
  summary.axis = identify::axis_name(triad.sensor, axis);
  for (const identify::TermKind kind : kIeeeKinds) {
    summary.cells.push_back(ieee_cell(fit.find(identify::term_kind_name(kind)), display_unit(triad.sensor, kind)));
  }
  std::string others;
  for (const identify::TermEstimate* term : identify::terms_in_report_order(fit)) {
    if (is_ieee_kind(term->kind) || term->status == identify::TermStatus::kAbsent) continue;
    const identify::UnitScale unit = display_unit(triad.sensor, term->kind);
    others +=
        (others.empty() ? "" : "; ") + term->name + " " + ieee_cell(term, unit) + " " + unit.key + format_shape(*term);
  }
  if (!others.empty()) summary.lines_below.push_back("also in the model: " + others);
  return summary;
}

std::string format_ieee_table(const std::vector<identify::TriadFit>& triads) {
  std::string text;
  for (const identify::TriadFit& triad : triads) {
    std::vector<std::string> heads;
    for (const identify::TermKind kind : kIeeeKinds) {
      heads.push_back(identify::amplitude_symbol(kind) + " [" + display_unit(triad.sensor, kind).key + "]");
    }
    std::vector<AxisSummary> axes;
    for (int axis = 0; axis < 3; ++axis) axes.push_back(axis_summary(triad, axis));
    // Each column as wide as its widest cell (the ± sign is one column, two bytes).
    const auto width = [](const std::string& cell) {
      return cell.size() - (cell.find("±") == std::string::npos ? 0 : 1);
    };
    std::vector<std::size_t> widths;
    for (std::size_t column = 0; column < heads.size(); ++column) {
      std::size_t widest = width(heads[column]);
      for (const AxisSummary& axis : axes) widest = std::max(widest, width(axis.cells[column]));
      widths.push_back(widest);
    }
    const auto row = [&](const std::string& first, const std::vector<std::string>& cells) {
      std::string line = "  " + first + std::string(first.size() < 9 ? 9 - first.size() : 1, ' ');
      for (std::size_t column = 0; column < cells.size(); ++column) {
        line += cells[column];
        if (column + 1 < cells.size()) line += std::string(widths[column] - width(cells[column]) + 3, ' ');
      }
      return line + "\n";
    };
    text += row(identify::sensor_prefix(triad.sensor), heads);
    for (const AxisSummary& axis : axes) {
      text += row(axis.axis, axis.cells);
      for (const std::string& line : axis.lines_below) text += wrapped("           " + line);
    }
  }
  return text;
}

std::string format_grouped_findings(const std::vector<identify::TriadFit>& triads) {
  // kind -> "gyro_x K, R; gyro_y K"
  std::map<identify::FindingKind, std::string> lines;
  for (const identify::TriadFit& triad : triads) {
    for (int axis = 0; axis < 3; ++axis) {
      std::map<identify::FindingKind, std::string> items;
      for (const identify::FitFinding& finding : triad.axes[axis].findings) {
        std::string& list = items[finding.kind];
        list += (list.empty() ? "" : ", ") + finding_item(finding, triad.sensor);
      }
      for (const auto& [kind, list] : items) {
        std::string& line = lines[kind];
        line += (line.empty() ? "" : "; ") + identify::axis_name(triad.sensor, axis) + " " + list;
      }
    }
  }
  std::string text;
  for (const auto& [kind, list] : lines) text += wrapped("  " + std::string(finding_meaning(kind)) + ": " + list);
  return text;
}

std::size_t warning_count(const std::vector<identify::TriadFit>& triads) {
  std::size_t count = 0;
  for (const identify::TriadFit& triad : triads) {
    for (const identify::FitResult& fit : triad.axes) count += fit.warnings.size();
  }
  return count;
}

}  // namespace pipeline
}  // namespace imu_lab
