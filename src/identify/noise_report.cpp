#include "imu_lab/identify/noise_report.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/identify/fit_warnings.h"
#include "imu_lab/identify/profile_likelihood.h"
#include "imu_lab/identify/white_equivalent.h"

namespace imu_lab {
namespace identify {

namespace {

constexpr const char* kFormatName = "imu_lab_noise_report";

void emit_number(YAML::Emitter& out, const std::string& key, double value) {
  if (!std::isfinite(value)) return;  // absent quantities are left out, never written as NaN
  out << YAML::Key << key << YAML::Value << value;
}

// value, sigma, intervals and bound of one parameter in every unit it is reported in.
void emit_parameter(YAML::Emitter& out, const std::string& symbol, const std::vector<UnitScale>& units,
                    const ParameterEstimate& estimate, double confidence) {
  // The limits in SI, once: with a structure mixture each is a quantile search.
  const bool has_interval = std::isfinite(estimate.log_sigma);
  const double low_68 = has_interval ? estimate.interval_low(1.0) : std::nan("");
  const double high_68 = has_interval ? estimate.interval_high(1.0) : std::nan("");
  const double low_95 = has_interval ? estimate.interval_low(1.959964) : std::nan("");
  const double high_95 = has_interval ? estimate.interval_high(1.959964) : std::nan("");
  for (const UnitScale& unit : units) {
    const std::string key = parameter_key(symbol, unit.key);
    emit_number(out, key, estimate.value * unit.per_si);
    emit_number(out, key + "_sigma", estimate.sigma * unit.per_si);
    if (has_interval) {
      emit_number(out, key + "_68_low", low_68 * unit.per_si);
      emit_number(out, key + "_68_high", high_68 * unit.per_si);
      emit_number(out, key + "_95_low", low_95 * unit.per_si);
      emit_number(out, key + "_95_high", high_95 * unit.per_si);
    }
    emit_number(out, key + upper_bound_suffix(confidence), estimate.upper_bound * unit.per_si);
    emit_number(out, key + upper_bound_suffix(kOneSigmaConfidence), estimate.upper_bound_one_sigma * unit.per_si);
  }
}

void emit_term(YAML::Emitter& out, SensorKind sensor, const TermEstimate& term, double confidence) {
  out << YAML::Key << term.name << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "status" << YAML::Value << term_status_name(term.status);
  out << YAML::Key << "borderline" << YAML::Value << term.borderline;
  out << YAML::Key << "sigma_source" << YAML::Value << sigma_source_name(term.sigma_source);
  emit_number(out, "selection_statistic", term.selection_statistic);
  emit_number(out, "selection_threshold", term.selection_threshold);
  emit_parameter(out, amplitude_symbol(term.kind), amplitude_units(sensor, term.kind), term.amplitude, confidence);
  // A white rate's shape is the front end's corner, reported in front_end.
  if (has_shape(term.kind) && term.kind != TermKind::kWhiteRate) {
    out << YAML::Key << "shape_fitted" << YAML::Value << term.shape_fitted;
    emit_parameter(out, shape_symbol(term.kind), shape_units(term.kind), term.shape, confidence);
  }
  if (!width_symbol(term.kind).empty()) {
    emit_parameter(out, width_symbol(term.kind), shape_units(term.kind), term.width, confidence);
  }
  out << YAML::EndMap;
}

// The sensor's front end: the low-pass on the white noise (fitted or given) and the output's
// quantization step (from the data).
void emit_front_end(YAML::Emitter& out, SensorKind sensor, const FitResult& fit) {
  out << YAML::Key << "front_end" << YAML::Value << YAML::BeginMap;
  const TermEstimate* white = fit.find("white_rate");
  if (white != nullptr && std::isfinite(white->shape.value)) {
    out << YAML::Key << "low_pass" << YAML::Value << (white->shape_fitted ? "fitted" : "given");
    emit_parameter(out, shape_symbol(TermKind::kWhiteRate), shape_units(TermKind::kWhiteRate), white->shape,
                   fit.options.upper_bound_confidence);
  } else {
    out << YAML::Key << "low_pass" << YAML::Value << "none";
  }
  emit_number(out, "output_quantization_step_" + rate_unit_key(sensor),
              fit.options.output_quantization_step > 0.0 ? fit.options.output_quantization_step : std::nan(""));
  out << YAML::EndMap;
}

void emit_band(YAML::Emitter& out, const FitResult& fit) {
  int inside = 0;
  for (const BandPoint& point : fit.band) inside += point.inside() ? 1 : 0;
  out << YAML::Key << "band_check" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "note" << YAML::Value
      << "fitted total against the measured deviation's chi-squared band at the fitted model's EDF, never "
         "narrower than +-1 %";
  emit_number(out, "confidence", kBandConfidence);
  out << YAML::Key << "points" << YAML::Value << static_cast<int>(fit.band.size());
  out << YAML::Key << "inside" << YAML::Value << inside;
  out << YAML::Key << "outside_ranges" << YAML::Value << YAML::BeginSeq;
  for (const BandExcursion& excursion : band_excursions(fit.band)) {
    out << YAML::BeginMap;
    emit_number(out, "first_tau_s", excursion.first_tau_s);
    emit_number(out, "last_tau_s", excursion.last_tau_s);
    out << YAML::Key << "points" << YAML::Value << excursion.point_count;
    emit_number(out, "largest_excursion_percent_of_deviation", 100.0 * excursion.largest_excursion);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
}

void emit_graphical(YAML::Emitter& out, SensorKind sensor, const GraphicalReadings& readings) {
  const std::string rate = rate_unit_key(sensor);
  const auto n_units = amplitude_units(sensor, TermKind::kWhiteRate);
  const auto b_units = amplitude_units(sensor, TermKind::kBiasInstability);
  const auto k_units = amplitude_units(sensor, TermKind::kRandomWalk);
  out << YAML::Key << "graphical_readings" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "note" << YAML::Value
      << "IEEE 952 graphical readings, correct for a single term only; the fit is the estimate. "
         "N_upper_bound_slope_ray bounds N only where no anti-alias filter pulls the leftmost points "
         "down: behind a front end (front_end above) it can lie below N";
  for (const UnitScale& unit : n_units) {
    emit_number(out, parameter_key("N_upper_bound_slope_ray", unit.key), readings.white_rate_upper_bound * unit.per_si);
    emit_number(out, parameter_key("N_slope_reading_at_1s", unit.key), readings.white_rate_at_1s * unit.per_si);
  }
  for (const UnitScale& unit : k_units) {
    emit_number(out, parameter_key("K_slope_reading_at_3s", unit.key), readings.random_walk_at_3s * unit.per_si);
  }
  for (const UnitScale& unit : b_units) {
    emit_number(out, parameter_key("B_flat_tangent_at_minimum", unit.key),
                readings.bias_instability_from_minimum * unit.per_si);
  }
  emit_number(out, "minimum_deviation_" + rate, readings.minimum_deviation);
  emit_number(out, "tau_at_minimum_s", readings.tau_at_minimum_s);
  out << YAML::EndMap;
}

// The white density a filter designer needs (white_equivalent.h), next to the fitted terms it
// is made of; kalibr_imu.yaml carries the same number.
void emit_white_equivalent(YAML::Emitter& out, SensorKind sensor, const FitResult& fit) {
  const double density = white_equivalent_density(fit);
  if (!std::isfinite(density)) return;
  out << YAML::Key << "white_equivalent" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "note" << YAML::Value
      << "N plus, in power, each Markov term with T_c below twice tau0 (white noise behind the sensor's "
         "low-pass, which the curve cannot tell from white); kalibr_imu.yaml's noise density";
  for (const UnitScale& unit : amplitude_units(sensor, TermKind::kWhiteRate)) {
    emit_number(out, parameter_key(amplitude_symbol(TermKind::kWhiteRate), unit.key), density * unit.per_si);
  }
  out << YAML::EndMap;
}

// Each line or resonance's other description and its weight in the sigmas and intervals
// (structure_doubt.h).
void emit_structure_doubt(YAML::Emitter& out, const FitResult& fit) {
  if (fit.structure_alternatives.empty()) return;
  out << YAML::Key << "structure_doubt" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "note" << YAML::Value
      << "each peak fitted again as the other kind (a line as a resonance, a resonance as a line) and each "
         "left-out term added; the sigmas of the reported terms include the spread between these structures "
         "and the selected one, weighed by Akaike's criterion, and their intervals are the quantiles of the "
         "weighed structures' mixture (doc/identification.md)";
  out << YAML::Key << "alternatives" << YAML::Value << YAML::BeginSeq;
  for (const StructureAlternative& alternative : fit.structure_alternatives) {
    out << YAML::Flow << YAML::BeginMap;
    if (alternative.replaced.empty()) {
      out << YAML::Key << "added" << YAML::Value << alternative.replacement;
    } else {
      out << YAML::Key << "replaced" << YAML::Value << alternative.replaced;
      out << YAML::Key << "by" << YAML::Value << alternative.replacement;
    }
    emit_number(out, "peak_frequency_hz", alternative.peak_frequency_hz);
    emit_number(out, "distance_change", alternative.distance_change);
    out << YAML::Key << "parameter_change" << YAML::Value << alternative.parameter_change;
    emit_number(out, "weight", alternative.weight);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::EndMap;
}

void emit_axis(YAML::Emitter& out, SensorKind sensor, const std::string& name, const FitResult& fit) {
  out << YAML::Key << name << YAML::Value << YAML::BeginMap;
  emit_number(out, "tau0_s", fit.tau0_s);
  emit_number(out, "record_length_s", fit.record_length_s);
  out << YAML::Key << "terms" << YAML::Value << YAML::BeginMap;
  for (const TermEstimate* term : terms_in_report_order(fit)) {
    emit_term(out, sensor, *term, fit.options.upper_bound_confidence);
  }
  out << YAML::EndMap;
  emit_front_end(out, sensor, fit);
  emit_white_equivalent(out, sensor, fit);
  out << YAML::Key << "fit_quality" << YAML::Value << YAML::BeginMap;
  emit_number(out, "distance", fit.quality.distance);
  out << YAML::Key << "points" << YAML::Value << fit.quality.points;
  out << YAML::Key << "parameters" << YAML::Value << fit.quality.parameters;
  out << YAML::Key << "degrees_of_freedom" << YAML::Value << fit.quality.degrees_of_freedom;
  emit_number(out, "distance_per_dof", fit.quality.distance_per_dof);
  emit_number(out, "p_value", fit.quality.p_value);
  emit_number(out, "discrepancy_relative_avar", fit.quality.discrepancy);
  out << YAML::EndMap;
  emit_band(out, fit);
  emit_graphical(out, sensor, fit.graphical);
  out << YAML::Key << "warnings" << YAML::Value << YAML::BeginSeq;
  for (const std::string& warning : fit.warnings) out << warning;
  out << YAML::EndSeq;
  out << YAML::Key << "selection" << YAML::Value << YAML::BeginSeq;
  for (const SelectionStep& step : fit.selection_steps) {
    std::ostringstream line;
    line << step.action << " " << step.term;
    if (step.action != "start") {
      line << " (change of the distance " << step.lr_statistic << ", threshold " << step.threshold << ")";
    }
    out << line.str();
  }
  out << YAML::EndSeq;
  emit_structure_doubt(out, fit);
  out << YAML::EndMap;
}

}  // namespace

std::string parameter_key(const std::string& symbol, const std::string& unit_key) { return symbol + "_" + unit_key; }

std::string upper_bound_suffix(double confidence) {
  return "_upper_" + std::to_string(static_cast<int>(std::lround(100.0 * confidence)));
}

namespace {
void emit_events(YAML::Emitter& out, const ReportMetadata& metadata) {
  out << YAML::Key << "events" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "screened" << YAML::Value << metadata.events_screened;
  if (metadata.events_screened) {
    out << YAML::Key << "count" << YAML::Value << metadata.event_count;
    out << YAML::Key << "effect" << YAML::Value
        << "each event's samples were left out and the record split there (a bias step it left lies between "
           "two pooled segments): the curves and this fit never saw it";
    out << YAML::Key << "listed" << YAML::Value << YAML::BeginSeq;
    for (const ReportEvent& event : metadata.events) {
      out << YAML::Flow << YAML::BeginMap;
      emit_number(out, "onset_s", event.onset_s);
      emit_number(out, "window_start_s", event.window_start_s);
      emit_number(out, "window_end_s", event.window_end_s);
      out << YAML::Key << "peak_channel" << YAML::Value << event.peak_channel;
      emit_number(out, "peak_sigma", event.peak_sigma);
      out << YAML::Key << "dropped_samples" << YAML::Value << event.dropped_samples;
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
}

void emit_level_shifts(YAML::Emitter& out, const ReportMetadata& metadata) {
  out << YAML::Key << "level_shifts" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "screened" << YAML::Value << metadata.level_shifts_screened;
  if (metadata.level_shifts_screened) {
    out << YAML::Key << "count" << YAML::Value << metadata.level_shift_count;
    out << YAML::Key << "effect" << YAML::Value
        << "the stepping triad's samples around each step were left out and its record split there: the step "
           "lies between two pooled segments, so the curves and this fit never saw it";
    out << YAML::Key << "listed" << YAML::Value << YAML::BeginSeq;
    for (const ReportLevelShift& shift : metadata.level_shifts) {
      out << YAML::Flow << YAML::BeginMap;
      emit_number(out, "step_s", shift.step_s);
      emit_number(out, "window_start_s", shift.window_start_s);
      emit_number(out, "window_end_s", shift.window_end_s);
      out << YAML::Key << "peak_channel" << YAML::Value << shift.peak_channel;
      emit_number(out, "peak_sigma", shift.peak_sigma);
      for (const auto& step : shift.shifts) emit_number(out, "shift_" + step.first, step.second);
      out << YAML::Key << "masked_samples" << YAML::Value << shift.masked_samples;
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
}
}  // namespace

std::string format_noise_report(const std::vector<TriadFit>& triads, const ReportMetadata& metadata) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::Comment(
      "imu_lab noise identification (doc/formats.md, noise.yaml). SI and field units, the unit in every key. Per axis "
      "the five IEEE Std 952 terms come first (N, B, K, Q, R), then the others; the front end (low-pass, "
      "output quantization) has its own block. Each value has its one-sigma and its 68 % and 95 % "
      "intervals (symmetric in the logarithm); an absent or unconstrained term has an upper bound. "
      "sigma_source: moment_covariance (the fit's own, default) or bootstrap.");
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << kFormatName;
  out << YAML::Key << "version" << YAML::Value << 2;
  out << YAML::Key << "source" << YAML::Value << metadata.source;
  emit_number(out, "update_rate_hz", metadata.update_rate_hz);
  emit_events(out, metadata);
  emit_level_shifts(out, metadata);
  out << YAML::Key << "triads" << YAML::Value << YAML::BeginMap;
  for (const TriadFit& triad : triads) {
    out << YAML::Key << sensor_prefix(triad.sensor) << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "worst_axis" << YAML::Value << axis_name(triad.sensor, triad.worst_axis);
    out << YAML::Key << "worst_axis_reason" << YAML::Value << triad.worst_axis_reason;
    out << YAML::Key << "axes" << YAML::Value << YAML::BeginMap;
    for (int axis = 0; axis < 3; ++axis) {
      emit_axis(out, triad.sensor, axis_name(triad.sensor, axis), triad.axes[axis]);
    }
    out << YAML::EndMap << YAML::EndMap;
  }
  out << YAML::EndMap << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

void write_noise_report(const std::string& path, const std::vector<TriadFit>& triads, const ReportMetadata& metadata) {
  write_file_atomically(path, format_noise_report(triads, metadata));
}

std::map<std::string, double> read_noise_report_values(const std::string& yaml_text) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& error) {
    throw InputError(std::string("noise report: not YAML: ") + error.what());
  }
  if (!root.IsMap() || !root["format"] || root["format"].as<std::string>() != kFormatName) {
    throw InputError(std::string("noise report: missing 'format: ") + kFormatName + "'");
  }
  std::map<std::string, double> values;
  const std::function<void(const YAML::Node&, const std::string&)> walk = [&](const YAML::Node& node,
                                                                              const std::string& path) {
    if (node.IsMap()) {
      for (const auto& entry : node) {
        const std::string key = entry.first.as<std::string>();
        walk(entry.second, path.empty() ? key : path + "." + key);
      }
    } else if (node.IsScalar()) {
      double value = 0.0;
      if (YAML::convert<double>::decode(node, value)) values[path] = value;
    }
  };
  walk(root, "");
  return values;
}

namespace {

std::string report_file_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read noise report " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A finite number at `node`, or InputError naming the dotted key.
double reported_number(const YAML::Node& node, const std::string& key) {
  double value = 0.0;
  if (!node || !node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
    throw InputError("noise report: " + key + " is missing or not a finite number");
  }
  return value;
}

// "markov_2" -> markov: report names number the kinds that can repeat (term_names).
TermKind reported_kind(const std::string& name) {
  std::string kind = name;
  const std::size_t underscore = kind.rfind('_');
  if (underscore != std::string::npos && underscore + 1 < kind.size() &&
      kind.find_first_not_of("0123456789", underscore + 1) == std::string::npos) {
    kind.resize(underscore);
  }
  return term_kind_from_name(kind);
}
}  // namespace

std::vector<ReportedAxisModel> read_reported_axis_models(const std::string& yaml_text, SensorKind sensor) {
  read_noise_report_values(yaml_text);  // the format check
  const YAML::Node root = YAML::Load(yaml_text);
  const std::string triad_key = "triads." + sensor_prefix(sensor);
  // Step by step: indexing a missing node again throws yaml-cpp's own error.
  const YAML::Node triads = root["triads"];
  const YAML::Node triad = triads && triads.IsMap() ? triads[sensor_prefix(sensor)] : YAML::Node();
  const YAML::Node axes = triad && triad.IsMap() ? triad["axes"] : YAML::Node();
  if (!axes || !axes.IsMap()) throw InputError("noise report: no " + triad_key + ".axes (was that triad identified?)");
  std::vector<ReportedAxisModel> models;
  for (int axis = 0; axis < 3; ++axis) {
    ReportedAxisModel reported;
    reported.axis = axis_name(sensor, axis);
    const std::string axis_key = triad_key + ".axes." + reported.axis;
    const YAML::Node node = axes[reported.axis];
    if (!node || !node.IsMap()) throw InputError("noise report: no " + axis_key);
    reported.tau0_s = reported_number(node["tau0_s"], axis_key + ".tau0_s");
    const YAML::Node terms = node["terms"];
    if (!terms || !terms.IsMap()) throw InputError("noise report: no " + axis_key + ".terms");
    for (const auto& entry : terms) {
      const std::string name = entry.first.as<std::string>();
      const std::string term_key = axis_key + ".terms." + name;
      if (!entry.second.IsMap()) throw InputError("noise report: " + term_key + " is not a map");
      const YAML::Node status = entry.second["status"];
      if (!status || !status.IsScalar()) throw InputError("noise report: no " + term_key + ".status");
      if (status.as<std::string>() != "present") continue;
      Term term;
      try {
        term.kind = reported_kind(name);
      } catch (const std::invalid_argument&) {
        throw InputError("noise report: " + term_key + " is not a term imu_lab knows");
      }
      const std::string amplitude =
          parameter_key(amplitude_symbol(term.kind), amplitude_units(sensor, term.kind)[0].key);
      term.amplitude = reported_number(entry.second[amplitude], term_key + "." + amplitude);
      if (has_shape(term.kind) && term.kind != TermKind::kWhiteRate) {
        const std::string shape = parameter_key(shape_symbol(term.kind), shape_units(term.kind)[0].key);
        term.shape = reported_number(entry.second[shape], term_key + "." + shape);
      }
      if (!width_symbol(term.kind).empty()) {
        const std::string width = parameter_key(width_symbol(term.kind), shape_units(term.kind)[0].key);
        term.width = reported_number(entry.second[width], term_key + "." + width);
      }
      reported.model.terms.push_back(term);
    }
    const YAML::Node front_end = node["front_end"] && node["front_end"].IsMap() ? node["front_end"] : YAML::Node();
    const YAML::Node low_pass = front_end ? front_end["low_pass"] : YAML::Node();
    if (low_pass && low_pass.IsScalar() && low_pass.as<std::string>() != "none") {
      const std::string corner =
          parameter_key(shape_symbol(TermKind::kWhiteRate), shape_units(TermKind::kWhiteRate)[0].key);
      const double corner_hz = reported_number(front_end[corner], axis_key + ".front_end." + corner);
      for (Term& term : reported.model.terms) {
        if (term.kind == TermKind::kWhiteRate) term.shape = corner_hz;
      }
    }
    const std::string step_key = "output_quantization_step_" + rate_unit_key(sensor);
    if (front_end && front_end[step_key]) {
      const double step = reported_number(front_end[step_key], axis_key + ".front_end." + step_key);
      reported.model.output_quantization_density = step * std::sqrt(reported.tau0_s / 12.0);
    }
    models.push_back(reported);
  }
  return models;
}

std::map<std::string, double> read_noise_report_file(const std::string& path) {
  const std::string text = report_file_text(path);
  try {
    return read_noise_report_values(text);
  } catch (const InputError& error) {
    throw InputError(path + ": " + error.what());
  }
}

std::vector<ReportedAxisModel> load_reported_axis_models(const std::string& path, SensorKind sensor) {
  const std::string text = report_file_text(path);
  try {
    return read_reported_axis_models(text, sensor);
  } catch (const InputError& error) {
    throw InputError(path + ": " + error.what());
  }
}

}  // namespace identify
}  // namespace imu_lab
