#include "imu_lab/repeatability/lot.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <tuple>

#include "imu_lab/common/format_number.h"
#include "imu_lab/identify/fit.h"
#include "imu_lab/identify/noise_report.h"
#include "imu_lab/identify/units.h"

namespace imu_lab {
namespace repeatability {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

identify::SensorKind sensor_of(const std::string& channel) {
  return channel.rfind("gyro", 0) == 0 ? identify::SensorKind::kGyroscope : identify::SensorKind::kAccelerometer;
}

// "markov_2" -> kMarkov: numbered kinds carry their rank after the kind's name (noise_model.h).
identify::TermKind kind_of(const std::string& term) {
  const std::size_t underscore = term.rfind('_');
  if (underscore != std::string::npos && underscore + 1 < term.size() &&
      std::all_of(term.begin() + underscore + 1, term.end(), [](unsigned char c) { return std::isdigit(c); })) {
    return identify::term_kind_from_name(term.substr(0, underscore));
  }
  return identify::term_kind_from_name(term);
}

// "triads.<triad>.axes.<channel>."
std::string axis_prefix(const std::string& channel) {
  return "triads." + identify::sensor_prefix(sensor_of(channel)) + ".axes." + channel + ".";
}

const double* find_value(const std::map<std::string, double>& values, const std::string& key) {
  const auto found = values.find(key);
  return found == values.end() ? nullptr : &found->second;
}

// The largest "<key>_upper_<confidence>" a report gives for a parameter (NaN: none).
double upper_bound_of(const std::map<std::string, double>& values, const std::string& key) {
  const std::string prefix = key + "_upper_";
  double bound = kNaN;
  for (auto it = values.lower_bound(prefix); it != values.end() && it->first.rfind(prefix, 0) == 0; ++it) {
    if (!(bound >= it->second)) bound = it->second;
  }
  return bound;
}

// The (channel, term) pairs any unit reports, in channel order and then TermKind order.
std::vector<std::pair<std::string, std::string>> reported_terms(const std::vector<LotUnit>& units) {
  std::set<std::tuple<std::size_t, int, std::string>> found;
  for (const LotUnit& unit : units) {
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      const std::string prefix = axis_prefix(kChannelNames[c]) + "terms.";
      for (auto it = unit.report_values.lower_bound(prefix);
           it != unit.report_values.end() && it->first.rfind(prefix, 0) == 0; ++it) {
        const std::string term = it->first.substr(prefix.size(), it->first.find('.', prefix.size()) - prefix.size());
        found.insert({c, static_cast<int>(kind_of(term)), term});
      }
    }
  }
  std::vector<std::pair<std::string, std::string>> terms;
  for (const auto& [channel, kind, term] : found) terms.push_back({kChannelNames[channel], term});
  return terms;
}

void emit_number(YAML::Emitter& out, const std::string& key, double value) {
  if (std::isfinite(value)) out << YAML::Key << key << YAML::Value << value;
}

std::string csv_number(double value) { return std::isfinite(value) ? format_number(value) : ""; }

// Four significant digits for a page read by people; the CSV and YAML keep full precision.
std::string page_number(double value) { return std::isfinite(value) ? format_number(value, 4) : "-"; }

}  // namespace

LotSummary lot_summary(const std::vector<LotUnit>& units, double confidence) {
  if (units.size() < 2) throw std::invalid_argument("a lot needs at least 2 units");
  LotSummary summary;
  summary.confidence = confidence;
  for (const LotUnit& unit : units) {
    if (std::find(summary.units.begin(), summary.units.end(), unit.name) != summary.units.end()) {
      throw std::invalid_argument("two units are named " + unit.name + "; give each unit its own name");
    }
    summary.units.push_back(unit.name);
    if (identified_terms(unit.report_values).empty()) {
      throw std::invalid_argument("unit " + unit.name + ": its noise report identifies no term");
    }
  }
  for (const auto& [channel, term_name] : reported_terms(units)) {
    LotTerm term;
    term.channel = channel;
    term.term = term_name;
    const identify::TermKind kind = kind_of(term_name);
    term.field_unit = identify::field_amplitude_unit(sensor_of(channel), kind).key;
    term.parameter = identify::parameter_key(identify::amplitude_symbol(kind), term.field_unit);
    const std::string key = axis_prefix(channel) + "terms." + term_name + "." + term.parameter;
    term.absent_upper_bound_max = kNaN;
    std::vector<double> values;
    for (const LotUnit& unit : units) {
      const double* value = find_value(unit.report_values, key);
      if (value == nullptr) {
        term.absent_units.push_back(unit.name);
        const double bound = upper_bound_of(unit.report_values, key);
        if (std::isfinite(bound) && !(term.absent_upper_bound_max >= bound)) term.absent_upper_bound_max = bound;
        continue;
      }
      const double* sigma = find_value(unit.report_values, key + "_sigma");
      term.identified.push_back({unit.name, *value, sigma != nullptr ? *sigma : kNaN});
      values.push_back(*value);
    }
    term.typical = values.empty() ? kNaN : median_of(values);
    term.worst = values.empty() ? kNaN : *std::max_element(values.begin(), values.end());
    if (values.size() >= 2) term.spread = spread_of(values, confidence);
    summary.terms.push_back(std::move(term));
  }
  return summary;
}

identify::NoiseModel typical_model(const std::vector<LotUnit>& units, const std::string& channel) {
  const identify::SensorKind sensor = sensor_of(channel);
  const std::string prefix = axis_prefix(channel);
  // The SI key of a parameter (the first unit a report gives), or "" for none.
  const auto si_key = [](const std::string& symbol, const std::vector<identify::UnitScale>& scales) {
    return symbol.empty() || scales.empty() ? std::string() : identify::parameter_key(symbol, scales.front().key);
  };
  // Median over the units that give the key; `fallback` where none does.
  const auto median_over_units = [&units](const std::string& key, double fallback) {
    std::vector<double> values;
    for (const LotUnit& unit : units) {
      if (const double* value = find_value(unit.report_values, key)) values.push_back(*value);
    }
    return values.empty() ? fallback : median_of(values);
  };
  identify::NoiseModel model;
  for (const auto& [term_channel, term_name] : reported_terms(units)) {
    if (term_channel != channel) continue;
    const identify::TermKind kind = kind_of(term_name);
    const std::string term_prefix = prefix + "terms." + term_name + ".";
    const std::string amplitude_key =
        term_prefix + si_key(identify::amplitude_symbol(kind), identify::amplitude_units(sensor, kind));
    std::size_t identified = 0;
    for (const LotUnit& unit : units) identified += find_value(unit.report_values, amplitude_key) != nullptr ? 1 : 0;
    if (2 * identified < units.size()) continue;  // a minority's term is not the typical unit's
    identify::Term term;
    term.kind = kind;
    term.amplitude = median_over_units(amplitude_key, 0.0);
    const std::vector<identify::UnitScale> shape_scales = identify::shape_units(kind);
    if (kind == identify::TermKind::kWhiteRate) {
      term.shape = median_over_units(prefix + "front_end." + si_key(identify::shape_symbol(kind), shape_scales), 0.0);
    } else if (identify::has_shape(kind)) {
      term.shape = median_over_units(term_prefix + si_key(identify::shape_symbol(kind), shape_scales), 0.0);
    }
    if (!identify::width_symbol(kind).empty()) {
      term.width = median_over_units(term_prefix + si_key(identify::width_symbol(kind), shape_scales), 0.0);
    }
    model.terms.push_back(term);
  }
  std::vector<double> quantization;
  const std::string step_key = prefix + "front_end.output_quantization_step_" + identify::rate_unit_key(sensor);
  for (const LotUnit& unit : units) {
    const double* step = find_value(unit.report_values, step_key);
    const double* tau0 = find_value(unit.report_values, prefix + "tau0_s");
    quantization.push_back(step != nullptr && tau0 != nullptr ? identify::quantization_density(*step, *tau0) : 0.0);
  }
  model.output_quantization_density = median_of(quantization);
  return model;
}

std::string typical_model_csv(const std::vector<LotUnit>& units, const std::vector<double>& taus_s) {
  std::string text = "tau_s";
  std::vector<identify::NoiseModel> models;
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    text += std::string(",") + kChannelNames[c] + "_typical_dev_" + kChannelUnits[c];
    models.push_back(typical_model(units, kChannelNames[c]));
  }
  text += "\n";
  for (double tau_s : taus_s) {
    text += format_number(tau_s);
    for (const auto& model : models) {
      text +=
          "," + (model.terms.empty() ? std::string() : format_number(std::sqrt(identify::model_avar(model, tau_s))));
    }
    text += "\n";
  }
  return text;
}

std::string lot_csv(const LotSummary& summary) {
  std::string text = "channel,term,parameter,unit,value,sigma\n";
  for (const LotTerm& term : summary.terms) {
    const std::string row = term.channel + "," + term.term + "," + term.parameter + ",";
    for (const UnitTermValue& value : term.identified) {
      text += row + value.unit + "," + csv_number(value.value) + "," + csv_number(value.sigma) + "\n";
    }
    for (const std::string& unit : term.absent_units) text += row + unit + ",,\n";
    text += row + "typical," + csv_number(term.typical) + ",\n";
    text += row + "worst," + csv_number(term.worst) + ",\n";
    text += row + "spread," + csv_number(term.spread.count >= 2 ? term.spread.standard_deviation : kNaN) + ",\n";
  }
  return text;
}

std::string lot_yaml(const LotSummary& summary) {
  YAML::Emitter out;
  out.SetDoublePrecision(kRoundTripDigits);
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << "imu_lab_lot";
  out << YAML::Key << "units" << YAML::Value << YAML::Flow << summary.units;
  out << YAML::Key << "confidence" << YAML::Value << summary.confidence;
  out << YAML::Key << "terms" << YAML::Value << YAML::BeginSeq;
  for (const LotTerm& term : summary.terms) {
    out << YAML::BeginMap;
    out << YAML::Key << "channel" << YAML::Value << term.channel;
    out << YAML::Key << "term" << YAML::Value << term.term;
    out << YAML::Key << "parameter" << YAML::Value << term.parameter;
    out << YAML::Key << "identified_in" << YAML::Value << term.identified.size();
    emit_number(out, "typical_median", term.typical);
    emit_number(out, "worst_max", term.worst);
    if (term.spread.count >= 2) {
      out << YAML::Key << "spread" << YAML::Value << YAML::Flow << YAML::BeginMap;
      emit_number(out, "standard_deviation", term.spread.standard_deviation);
      emit_number(out, "lower", term.spread.lower);
      emit_number(out, "upper", term.spread.upper);
      out << YAML::EndMap;
    }
    out << YAML::Key << "units" << YAML::Value << YAML::BeginMap;
    for (const UnitTermValue& value : term.identified) {
      out << YAML::Key << value.unit << YAML::Value << YAML::Flow << YAML::BeginMap;
      emit_number(out, "value", value.value);
      emit_number(out, "sigma", value.sigma);
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
    if (!term.absent_units.empty()) {
      out << YAML::Key << "absent_in" << YAML::Value << YAML::Flow << term.absent_units;
      emit_number(out, "absent_upper_bound_max", term.absent_upper_bound_max);
    }
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::string lot_markdown(const LotSummary& summary) {
  std::string page = "# Lot of " + std::to_string(summary.units.size()) + " units\n\n";
  page +=
      "Typical = median over the units that identify the term, worst = the largest of them; spread = sample "
      "standard deviation (n - 1) over those units. A unit without the term is counted in `identified in`; "
      "`absent: < x` is the largest upper bound such units give. Per unit: value ± one sigma. See doc/lot.md.\n\n";
  page += "| channel | term | unit | typical | worst | spread | identified in |";
  for (const std::string& unit : summary.units) page += " " + unit + " |";
  page += "\n|---|---|---|---|---|---|---|";
  for (std::size_t k = 0; k < summary.units.size(); ++k) page += "---|";
  page += "\n";
  for (const LotTerm& term : summary.terms) {
    page += "| " + term.channel + " | " + term.term + " | " + term.field_unit + " | " + page_number(term.typical) +
            " | " + page_number(term.worst) + " | " +
            page_number(term.spread.count >= 2 ? term.spread.standard_deviation : kNaN) + " | " +
            std::to_string(term.identified.size()) + " of " + std::to_string(summary.units.size());
    if (std::isfinite(term.absent_upper_bound_max))
      page += " (absent: < " + page_number(term.absent_upper_bound_max) + ")";
    page += " |";
    for (const std::string& unit : summary.units) {
      const auto value = std::find_if(term.identified.begin(), term.identified.end(),
                                      [&unit](const UnitTermValue& v) { return v.unit == unit; });
      if (value == term.identified.end()) {
        page += " - |";
      } else {
        page += " " + page_number(value->value) +
                (std::isfinite(value->sigma) ? " ± " + page_number(value->sigma) : "") + " |";
      }
    }
    page += "\n";
  }
  return page;
}

}  // namespace repeatability
}  // namespace imu_lab
