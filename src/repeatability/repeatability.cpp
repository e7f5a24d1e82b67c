#include "imu_lab/repeatability/repeatability.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/confidence.h"
#include "imu_lab/common/format_number.h"

namespace imu_lab {
namespace repeatability {
namespace {

constexpr std::size_t kMinimumSamples = 16;

// Octave averaging factors up to a quarter of the run, so the last points still average a few
// independent clusters.
std::vector<int> octave_factors(std::size_t sample_count) {
  std::vector<int> factors;
  for (int m = 1; 4 * static_cast<std::size_t>(m) <= sample_count; m *= 2) factors.push_back(m);
  return factors;
}

void emit_spread(YAML::Emitter& out, const SpreadEstimate& spread) {
  out << YAML::BeginMap << YAML::Key << "runs" << YAML::Value << spread.count << YAML::Key << "mean" << YAML::Value
      << spread.mean << YAML::Key << "standard_deviation" << YAML::Value << spread.standard_deviation << YAML::Key
      << "lower" << YAML::Value << spread.lower << YAML::Key << "upper" << YAML::Value << spread.upper << YAML::Key
      << "confidence" << YAML::Value << spread.confidence << YAML::EndMap;
}

// The Allan deviation at tau_s beyond the curve: a straight line in log-log through the points of
// the last six octaves below tau_s, weighted by their EDF (one octave point alone has only a few
// degrees of freedom, and a slope from two of them scatters by a factor of ~1.5 at 4x the tau),
// its slope clamped to [-1/2, +1/2] (white rate to rate random walk).
double extrapolate_deviation(const std::vector<allan::StabilityPoint>& points, double tau_s) {
  std::vector<const allan::StabilityPoint*> used;
  for (const auto& point : points) {
    if (point.tau_s >= tau_s / 64.0 && point.deviation > 0.0) used.push_back(&point);
  }
  if (used.size() < 2) used = {&points[points.size() - 2], &points.back()};
  double weight = 0.0, mean_x = 0.0, mean_y = 0.0;
  for (const auto* point : used) {
    const double w = std::max(point->edf, 1.0);
    weight += w;
    mean_x += w * std::log(point->tau_s);
    mean_y += w * std::log(point->deviation);
  }
  mean_x /= weight;
  mean_y /= weight;
  double sxy = 0.0, sxx = 0.0;
  for (const auto* point : used) {
    const double w = std::max(point->edf, 1.0);
    const double dx = std::log(point->tau_s) - mean_x;
    sxy += w * dx * (std::log(point->deviation) - mean_y);
    sxx += w * dx * dx;
  }
  double slope = sxx > 0.0 ? sxy / sxx : -0.5;
  if (!std::isfinite(slope)) slope = -0.5;
  slope = std::clamp(slope, -0.5, 0.5);
  return std::exp(mean_y + slope * (std::log(tau_s) - mean_x));
}

}  // namespace

double median_of(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("a median needs at least 1 value");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

SpreadEstimate spread_of(const std::vector<double>& values, double confidence) {
  if (values.size() < 2) throw std::invalid_argument("a spread needs at least 2 values");
  SpreadEstimate spread;
  spread.count = values.size();
  spread.confidence = confidence;
  double sum = 0.0;
  for (double value : values) {
    if (!std::isfinite(value)) throw std::invalid_argument("a spread of values with NaN/Inf");
    sum += value;
  }
  spread.mean = sum / values.size();
  double squares = 0.0;
  for (double value : values) squares += (value - spread.mean) * (value - spread.mean);
  spread.standard_deviation = std::sqrt(squares / (values.size() - 1));
  // s^2 (n-1) / sigma^2 is chi-squared with n - 1 degrees of freedom for normal values: the same
  // bounds as a deviation with edf = n - 1.
  const auto bounds = allan::chi_squared_bounds(spread.standard_deviation, values.size() - 1.0, confidence);
  spread.lower = bounds.lower;
  spread.upper = bounds.upper;
  return spread;
}

std::vector<IdentifiedTerm> identified_terms(const std::map<std::string, double>& report_values) {
  const std::string sigma_suffix = "_sigma";
  std::vector<IdentifiedTerm> terms;
  for (const auto& [key, value] : report_values) {
    const auto sigma = report_values.find(key + sigma_suffix);
    if (sigma == report_values.end()) continue;
    // triads . <triad> . axes . <channel> . terms . <term> . <parameter>
    std::vector<std::string> parts;
    for (std::size_t begin = 0;;) {
      const std::size_t dot = key.find('.', begin);
      parts.push_back(key.substr(begin, dot == std::string::npos ? std::string::npos : dot - begin));
      if (dot == std::string::npos) break;
      begin = dot + 1;
    }
    if (parts.size() != 7 || parts[0] != "triads" || parts[2] != "axes" || parts[4] != "terms") continue;
    terms.push_back({parts[3], parts[5], parts[6], value, sigma->second});
  }
  return terms;
}

RunSummary summarise_run(const std::string& name, const std::vector<std::array<double, kChannelCount>>& samples,
                         double tau0_s) {
  if (samples.size() < kMinimumSamples) {
    throw std::invalid_argument("run " + name + " has " + std::to_string(samples.size()) + " samples; at least " +
                                std::to_string(kMinimumSamples) + " are needed");
  }
  if (!(tau0_s > 0.0)) throw std::invalid_argument("run " + name + ": the sample period must be positive");
  RunSummary run;
  run.name = name;
  run.sample_count = samples.size();
  run.duration_s = samples.size() * tau0_s;
  const std::vector<int> factors = octave_factors(samples.size());
  std::vector<double> centred(samples.size());
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    double sum = 0.0;
    for (const auto& row : samples) sum += row[c];
    const double mean = sum / samples.size();
    for (std::size_t i = 0; i < samples.size(); ++i) centred[i] = samples[i][c] - mean;  // small phase: round-off
    const auto points = allan::evaluate_frequency(allan::Statistic::kOverlappingAllan, centred, tau0_s, factors);
    if (points.size() < 2) throw std::invalid_argument("run " + name + " is too short for its Allan deviation");
    const auto smallest = std::min_element(points.begin(), points.end(),
                                           [](const auto& a, const auto& b) { return a.deviation < b.deviation; });
    RunChannel& channel = run.channels[c];
    channel.bias = mean;
    channel.mean_uncertainty = extrapolate_deviation(points, run.duration_s);
    channel.allan_minimum = smallest->deviation;
    channel.allan_minimum_tau_s = smallest->tau_s;
  }
  return run;
}

RepeatabilityTable repeatability_table(const std::vector<RunSummary>& runs, double confidence) {
  if (runs.size() < 2) throw std::invalid_argument("repeatability needs at least 2 runs");
  RepeatabilityTable table;
  table.runs = runs;
  table.confidence = confidence;
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    std::vector<double> biases, minima;
    double squares = 0.0;
    for (const RunSummary& run : runs) {
      biases.push_back(run.channels[c].bias);
      minima.push_back(run.channels[c].allan_minimum);
      squares += run.channels[c].mean_uncertainty * run.channels[c].mean_uncertainty;
    }
    table.bias_spread[c] = spread_of(biases, confidence);
    table.rms_mean_uncertainty[c] = std::sqrt(squares / runs.size());
    table.median_allan_minimum[c] = median_of(minima);
  }
  return table;
}

std::string repeatability_csv(const RepeatabilityTable& table) {
  std::string text = "run,channel,unit,bias,mean_uncertainty,allan_minimum,allan_minimum_tau_s,duration_s\n";
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    const std::string channel = std::string(kChannelNames[c]) + "," + kChannelUnits[c] + ",";
    for (const RunSummary& run : table.runs) {
      const RunChannel& r = run.channels[c];
      text += run.name + "," + channel + format_number(r.bias) + "," + format_number(r.mean_uncertainty) + "," +
              format_number(r.allan_minimum) + "," + format_number(r.allan_minimum_tau_s) + "," +
              format_number(run.duration_s) + "\n";
    }
    const SpreadEstimate& s = table.bias_spread[c];
    text += "mean," + channel + format_number(s.mean) + "," + format_number(table.rms_mean_uncertainty[c]) + "," +
            format_number(table.median_allan_minimum[c]) + ",,\n";
    text += "spread," + channel + format_number(s.standard_deviation) + ",,,,\n";
  }
  return text;
}

std::string repeatability_yaml(const RepeatabilityTable& table) {
  YAML::Emitter out;
  out.SetDoublePrecision(kRoundTripDigits);
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << "imu_lab_repeatability";
  out << YAML::Key << "confidence" << YAML::Value << table.confidence;
  out << YAML::Key << "channels" << YAML::Value << YAML::BeginMap;
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    out << YAML::Key << kChannelNames[c] << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "unit" << YAML::Value << kChannelUnits[c];
    out << YAML::Key << "run_to_run_bias" << YAML::Value;
    emit_spread(out, table.bias_spread[c]);
    out << YAML::Key << "rms_mean_uncertainty" << YAML::Value << table.rms_mean_uncertainty[c];
    out << YAML::Key << "median_allan_minimum" << YAML::Value << table.median_allan_minimum[c];
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  out << YAML::Key << "runs" << YAML::Value << YAML::BeginSeq;
  for (const RunSummary& run : table.runs) {
    out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << run.name << YAML::Key << "samples" << YAML::Value
        << run.sample_count << YAML::Key << "duration_s" << YAML::Value << run.duration_s;
    out << YAML::Key << "channels" << YAML::Value << YAML::BeginMap;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
      const RunChannel& r = run.channels[c];
      out << YAML::Key << kChannelNames[c] << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "bias"
          << YAML::Value << r.bias << YAML::Key << "mean_uncertainty" << YAML::Value << r.mean_uncertainty << YAML::Key
          << "allan_minimum" << YAML::Value << r.allan_minimum << YAML::Key << "allan_minimum_tau_s" << YAML::Value
          << r.allan_minimum_tau_s << YAML::EndMap;
    }
    out << YAML::EndMap;
    if (!run.terms.empty()) {
      out << YAML::Key << "identified_terms" << YAML::Value << YAML::BeginSeq;
      for (const IdentifiedTerm& term : run.terms) {
        out << YAML::Flow << YAML::BeginMap << YAML::Key << "channel" << YAML::Value << term.channel << YAML::Key
            << "term" << YAML::Value << term.term << YAML::Key << "value" << YAML::Value << term.value << YAML::Key
            << "sigma" << YAML::Value << term.sigma << YAML::Key << "parameter" << YAML::Value << term.parameter
            << YAML::EndMap;
      }
      out << YAML::EndSeq;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::vector<ParameterSpread> parameter_spreads(
    const std::vector<std::vector<std::pair<std::string, double>>>& calibrations, const std::string& unit,
    double confidence) {
  if (calibrations.size() < 2) throw std::invalid_argument("a calibration repeatability needs at least 2 calibrations");
  std::vector<ParameterSpread> spreads;
  for (const auto& parameter : calibrations.front()) spreads.push_back({parameter.first, unit, {}, {}});
  for (std::size_t k = 0; k < calibrations.size(); ++k) {
    if (calibrations[k].size() != spreads.size()) {
      throw std::invalid_argument("calibration " + std::to_string(k + 1) + " has " +
                                  std::to_string(calibrations[k].size()) + " parameters, the first " +
                                  std::to_string(spreads.size()));
    }
    for (std::size_t p = 0; p < spreads.size(); ++p) {
      if (calibrations[k][p].first != spreads[p].name) {
        throw std::invalid_argument("calibration " + std::to_string(k + 1) + " names " + calibrations[k][p].first +
                                    " where the first names " + spreads[p].name);
      }
      spreads[p].values.push_back(calibrations[k][p].second);
    }
  }
  for (ParameterSpread& spread : spreads) spread.spread = spread_of(spread.values, confidence);
  return spreads;
}

std::string parameter_spreads_csv(const std::vector<ParameterSpread>& spreads) {
  std::string text = "parameter,unit,calibrations,mean,standard_deviation,lower,upper,confidence\n";
  for (const ParameterSpread& p : spreads) {
    const SpreadEstimate& s = p.spread;
    text += p.name + "," + p.unit + "," + std::to_string(s.count) + "," + format_number(s.mean) + "," +
            format_number(s.standard_deviation) + "," + format_number(s.lower) + "," + format_number(s.upper) + "," +
            format_number(s.confidence) + "\n";
  }
  return text;
}

}  // namespace repeatability
}  // namespace imu_lab
