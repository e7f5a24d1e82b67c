#include "imu_lab/panel/allan_plot.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "imu_lab/common/format_number.h"
#include "imu_lab/identify/noise_model.h"

namespace imu_lab {
namespace panel {
namespace {

// The identification fits OADEV curves (doc/reference/nodes/allan_monitor.md); ADEV estimates the same variance.
// The other statistics have other expectations for the same noise, so the model is not drawn on them.
bool model_applies_to(const std::string& statistic) { return statistic == "oadev" || statistic == "adev"; }

// "markov_2" -> "markov": reports number the kinds that may appear more than once
// (identify::term_names).
std::string kind_name_of(const std::string& term_name) {
  const std::size_t underscore = term_name.find_last_of('_');
  if (underscore == std::string::npos || underscore + 1 == term_name.size()) return term_name;
  const bool numbered = std::all_of(term_name.begin() + underscore + 1, term_name.end(),
                                    [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
  return numbered ? term_name.substr(0, underscore) : term_name;
}

double finite_or_zero(double value) { return std::isfinite(value) ? value : 0.0; }

bool in_model(const NoiseTerm& term) { return term.status == "present" || term.status == "unconstrained"; }

// The limits of a set of log10 values as whole decades, at least one decade wide.
DecadeRange decades_enclosing(double low, double high) {
  DecadeRange range;
  range.low = static_cast<int>(std::floor(low));
  range.high = std::max(range.low + 1, static_cast<int>(std::ceil(high)));
  return range;
}

std::string percent_text(double fraction) { return format_number(100.0 * fraction, 3) + " %"; }

}  // namespace

std::string duration_text(double duration_s) {
  struct Unit {
    const char* name;
    double seconds;
  };
  static const Unit kUnits[] = {{"s", 1.0}, {"min", 60.0}, {"h", 3600.0}, {"d", 86400.0}};
  // Seconds below 100 s, minutes below 100 min, hours below two days: "90 s" reads better than
  // "1.5 min".
  const Unit* unit = &kUnits[0];
  if (duration_s >= 100.0) unit = &kUnits[1];
  if (duration_s >= 100.0 * 60.0) unit = &kUnits[2];
  if (duration_s >= 48.0 * 3600.0) unit = &kUnits[3];
  const double value = duration_s / unit->seconds;
  char text[64];
  if (value < 10.0) {
    std::snprintf(text, sizeof text, "%.2g %s", value, unit->name);
  } else {
    std::snprintf(text, sizeof text, "%.0f %s", value, unit->name);
  }
  return text;
}

std::vector<std::string> record_length_lines(const NoiseAxisModel& axis, double recorded_s) {
  std::vector<std::string> lines;
  for (const NoiseTerm& term : axis.terms) {
    if (!in_model(term) || std::isnan(term.required_record_length_s)) continue;
    const std::string label = term.symbol.empty() ? term.name : term.symbol;
    if (std::isinf(term.required_record_length_s)) {
      // identify::required_record_length_s searches up to 1e4 times the record the fit had.
      lines.push_back(label + ": not within 10000 x this record");
    } else if (term.required_record_length_s > recorded_s) {
      lines.push_back(label + ": about " + duration_text(term.required_record_length_s - recorded_s) + " more");
    } else {
      lines.push_back(label + ": resolved");
    }
  }
  return lines;
}

std::vector<PlotSeries> model_series(const NoiseAxisModel& axis, const std::vector<double>& tau_s) {
  std::vector<identify::Term> terms;
  std::vector<PlotSeries> series;
  PlotSeries total;
  total.label = "fit total";
  total.role = SeriesRole::kModelTotal;
  series.push_back(total);
  for (const NoiseTerm& term : axis.terms) {
    if (!in_model(term) || !(term.value > 0.0)) continue;
    identify::Term model_term;
    model_term.kind = identify::term_kind_from_name(kind_name_of(term.name));
    model_term.amplitude = term.value;
    model_term.shape = finite_or_zero(term.shape);
    model_term.width = finite_or_zero(term.width);
    terms.push_back(model_term);
    PlotSeries term_series;
    term_series.label = term.symbol.empty() ? term.name : term.symbol;
    term_series.role = SeriesRole::kModelTerm;
    term_series.constrained = term.status == "present";
    series.push_back(term_series);
  }
  // Rounding is white noise behind the front end: a white rate term of its density
  // (identify::partial_curves does the same).
  if (axis.output_quantization_density > 0.0) {
    terms.push_back({identify::TermKind::kWhiteRate, axis.output_quantization_density, 0.0, 0.0});
    PlotSeries rounding;
    rounding.label = "output rounding";
    rounding.role = SeriesRole::kModelTerm;
    series.push_back(rounding);
  }
  if (terms.empty()) return {};
  for (const double tau : tau_s) {
    if (!(tau > 0.0)) continue;
    const double log10_tau = std::log10(tau);
    double total_avar = 0.0;
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const double avar = identify::term_avar(terms[i], tau);
      total_avar += avar;
      if (avar > 0.0) series[i + 1].points.push_back({log10_tau, 0.5 * std::log10(avar)});
    }
    if (total_avar > 0.0) series[0].points.push_back({log10_tau, 0.5 * std::log10(total_avar)});
  }
  return series;
}

void AllanPanelModel::add_curves(StabilityCurves curves) {
  const std::string sensor = curves.sensor;
  const std::string statistic = curves.statistic;
  if (std::find(sensors_.begin(), sensors_.end(), sensor) == sensors_.end()) sensors_.push_back(sensor);
  std::vector<std::string>& statistics = statistics_[sensor];
  if (std::find(statistics.begin(), statistics.end(), statistic) == statistics.end()) {
    statistics.push_back(statistic);
  }
  curves_[{sensor, statistic}] = std::move(curves);
}

void AllanPanelModel::set_noise_report(NoiseReport report) {
  report_ = std::move(report);
  has_report_ = true;
}

std::vector<std::string> AllanPanelModel::statistics(const std::string& sensor) const {
  const auto found = statistics_.find(sensor);
  return found == statistics_.end() ? std::vector<std::string>() : found->second;
}

AllanPlot AllanPanelModel::plot(const std::string& sensor, const std::string& statistic, int axis) const {
  AllanPlot plot;
  const auto found = curves_.find({sensor, statistic});
  if (found == curves_.end() || axis < 0 || axis >= static_cast<int>(found->second.axes.size())) return plot;
  const StabilityCurves& curves = found->second;
  const StabilityAxis& channel = curves.axes[axis];
  plot.title = sensor + " " + channel.name + ", " + statistic + " (" + curves.unit + ")";
  plot.measured.label = statistic;
  plot.measured.role = SeriesRole::kMeasured;

  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  const auto widen = [&](double log10_value) {
    low = std::min(low, log10_value);
    high = std::max(high, log10_value);
  };
  std::vector<double> measured_tau_s;
  for (std::size_t i = 0; i < curves.tau_s.size() && i < channel.deviation.size(); ++i) {
    const double tau = curves.tau_s[i];
    const double deviation = channel.deviation[i];
    if (!(tau > 0.0) || !(deviation > 0.0) || !std::isfinite(deviation)) continue;
    const double log10_tau = std::log10(tau);
    measured_tau_s.push_back(tau);
    plot.measured.points.push_back({log10_tau, std::log10(deviation)});
    widen(std::log10(deviation));
    const double lower = i < channel.lower.size() ? channel.lower[i] : std::nan("");
    const double upper = i < channel.upper.size() ? channel.upper[i] : std::nan("");
    if (lower > 0.0 && std::isfinite(upper) && upper >= lower) {
      plot.band.push_back({log10_tau, std::log10(lower), std::log10(upper)});
      widen(std::log10(lower));
      widen(std::log10(upper));
    }
  }
  if (plot.measured.points.empty()) return plot;
  plot.tau_decades = decades_enclosing(plot.measured.points.front().log10_tau, plot.measured.points.back().log10_tau);

  const double recorded_s = static_cast<double>(curves.samples) * curves.tau0_s;
  plot.status_lines.push_back("recorded " + duration_text(recorded_s) + " (" + std::to_string(curves.samples) +
                              " samples), band " + percent_text(curves.confidence));

  if (!has_report_) {
    plot.status_lines.push_back("no noise report yet");
  } else {
    for (const std::string& problem : report_.problems) plot.status_lines.push_back("identification: " + problem);
    const std::string axis_name = sensor + "_" + channel.name;
    const auto model_axis = std::find_if(report_.axes.begin(), report_.axes.end(),
                                         [&](const NoiseAxisModel& candidate) { return candidate.axis == axis_name; });
    if (model_axis != report_.axes.end()) {
      plot.status_lines.push_back("model fitted on " + duration_text(report_.record_length_s) + " of record");
      if (model_applies_to(statistic)) {
        try {
          plot.model = model_series(*model_axis, measured_tau_s);
        } catch (const std::invalid_argument& error) {  // a term this build does not know
          plot.status_lines.push_back(std::string("model not drawn: ") + error.what());
        }
        // Terms fall far below the data at the ends of their range; the total never does.
        if (!plot.model.empty()) {
          for (const LogPoint& point : plot.model.front().points) widen(point.log10_deviation);
        }
      } else {
        plot.status_lines.push_back("model fitted on oadev: select oadev to compare");
      }
      plot.record_length_lines = record_length_lines(*model_axis, std::max(recorded_s, report_.record_length_s));
      if (!plot.record_length_lines.empty() && report_.target_relative_sigma > 0.0) {
        plot.record_length_lines.insert(plot.record_length_lines.begin(),
                                        "record for " + percent_text(report_.target_relative_sigma) + " (1 sigma):");
      }
    }
  }
  plot.deviation_decades = decades_enclosing(low, high);
  return plot;
}

}  // namespace panel
}  // namespace imu_lab
