#include "imu_lab/pipeline/allan_warm_up.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace pipeline {
namespace {

// The ramp |R| the Allan-Krobka dispersion removes: AVAR - AKVAR = <D>^2 / (2 tau^2) with
// <D> = R tau^2 for a ramp (doc/models.md), at the largest tau both curves have. 0 without one.
struct KrobkaRamp {
  double magnitude_per_s = 0.0;
  double tau_s = 0.0;
};

KrobkaRamp krobka_ramp(const allan::StreamingSnapshot& snapshot, std::size_t channel) {
  KrobkaRamp ramp;
  if (snapshot.curves.empty() || channel >= snapshot.channels.size()) return ramp;
  const auto& allan = snapshot.curve(allan::Statistic::kOverlappingAllan, channel);
  const auto& krobka = snapshot.curve(allan::Statistic::kAllanKrobka, channel);
  for (auto a = allan.rbegin(); a != allan.rend(); ++a) {
    for (const allan::StabilityPoint& k : krobka) {
      if (k.averaging_factor != a->averaging_factor) continue;
      const double difference = a->deviation * a->deviation - k.deviation * k.deviation;
      ramp.magnitude_per_s = std::sqrt(2.0 * std::max(0.0, difference)) / a->tau_s;
      ramp.tau_s = a->tau_s;
      return ramp;
    }
  }
  return ramp;
}

}  // namespace

void AllanWarmUp::remove_from(AllanSample& sample) const {
  const double time_s = static_cast<double>(sample.stamp_ns - first_stamp_ns) * 1e-9;
  for (std::size_t c = 0; c < kAllanChannelCount; ++c) {
    if (channels[c].fit) sample.values[c] -= channels[c].fit->transient(time_s);
  }
}

void check_warm_up_options(const AllanWarmUpOptions& options) {
  if (!(options.block_s > 0.0) || !std::isfinite(options.block_s)) {
    throw ConfigError("allan", "--warm-up-block-s", "must be a positive number of seconds (default 1)");
  }
}

AllanWarmUp fit_allan_warm_up(const thermal::WarmUpBlockMeans& blocks, const AllanWarmUpOptions& options) {
  AllanWarmUp warm_up;
  warm_up.block_s = options.block_s;
  warm_up.first_stamp_ns = blocks.first_stamp_ns();
  for (std::size_t c = 0; c < kAllanChannelCount && c < blocks.channel_count(); ++c) {
    const std::vector<thermal::WarmUpBlock> means = blocks.blocks(c);
    if (means.empty()) {
      warm_up.channels[c].problem = "no usable value";
      continue;
    }
    try {
      warm_up.channels[c].fit = thermal::fit_warm_up(means, options.block_s, options.fit);
    } catch (const std::invalid_argument& error) {
      warm_up.channels[c].problem = error.what();
    }
  }
  return warm_up;
}

std::string format_warm_up_yaml(AllanInput input, const AllanWarmUp& warm_up,
                                const allan::StreamingSnapshot& snapshot) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "model" << YAML::Value << "b(t) = constant + sum_k amplitude_k exp(-t / time_constant_k)";
  out << YAML::Key << "time_origin_stamp_ns" << YAML::Value << warm_up.first_stamp_ns;
  out << YAML::Key << "block_s" << YAML::Value << warm_up.block_s;
  out << YAML::Key << "removed" << YAML::Value << "the exponential terms, from every sample before the Allan analysis";
  out << YAML::Key << "sigmas" << YAML::Value
      << "least squares scaled by the residual variance and the residuals' long-run variance ratio "
         "(correlation_inflation)";
  out << YAML::Key << "channels" << YAML::Value << YAML::BeginMap;
  for (std::size_t c = 0; c < kAllanChannelCount; ++c) {
    const AllanWarmUpChannel& channel = warm_up.channels[c];
    const std::string unit = allan_value_unit(input, c);
    out << YAML::Key << kAllanChannelNames[c] << YAML::Value << YAML::BeginMap;
    if (!channel.fit) {
      out << YAML::Key << "problem" << YAML::Value << channel.problem;
      out << YAML::EndMap;
      continue;
    }
    const thermal::WarmUpFit& fit = *channel.fit;
    out << YAML::Key << "constant_" + unit << YAML::Value << fit.constant;
    out << YAML::Key << "constant_sigma_" + unit << YAML::Value << fit.constant_sigma;
    out << YAML::Key << "terms" << YAML::Value << YAML::BeginSeq;
    for (const thermal::WarmUpTerm& term : fit.terms) {
      out << YAML::Flow << YAML::BeginMap;
      out << YAML::Key << "amplitude_" + unit << YAML::Value << term.amplitude;
      out << YAML::Key << "amplitude_sigma_" + unit << YAML::Value << term.amplitude_sigma;
      out << YAML::Key << "time_constant_s" << YAML::Value << term.time_constant_s;
      out << YAML::Key << "time_constant_sigma_s" << YAML::Value << term.time_constant_sigma_s;
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
    out << YAML::Key << "added_term_p" << YAML::Value << YAML::Flow << fit.added_term_p;
    out << YAML::Key << "transient_at_start_" + unit << YAML::Value << fit.transient(0.0);
    out << YAML::Key << "transient_at_start_sigma_" + unit << YAML::Value << fit.transient_sigma(0.0);
    out << YAML::Key << "blocks" << YAML::Value << fit.block_count;
    out << YAML::Key << "residual_rms_" + unit << YAML::Value << fit.residual_rms;
    out << YAML::Key << "correlation_inflation" << YAML::Value << fit.correlation_inflation;
    out << YAML::Key << "trend_after_removal" << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "slope_" + unit + "_per_s" << YAML::Value << fit.trend.slope_per_s;
    out << YAML::Key << "slope_sigma_" + unit + "_per_s" << YAML::Value << fit.trend.slope_sigma_per_s;
    const KrobkaRamp ramp = krobka_ramp(snapshot, c);
    out << YAML::Key << std::string("krobka_ramp_magnitude_") + kAllanChannelUnits[c] + "_per_s" << YAML::Value
        << ramp.magnitude_per_s;
    out << YAML::Key << "krobka_ramp_tau_s" << YAML::Value << ramp.tau_s;
    out << YAML::EndMap;
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::string format_warm_up_lines(const std::string& prefix, AllanInput input, const AllanWarmUp& warm_up) {
  std::string text;
  char line[512];
  for (std::size_t c = 0; c < kAllanChannelCount; ++c) {
    const AllanWarmUpChannel& channel = warm_up.channels[c];
    text += prefix + kAllanChannelNames[c] + ": ";
    if (!channel.fit) {
      text += "not fitted: " + channel.problem + "\n";
      continue;
    }
    const thermal::WarmUpFit& fit = *channel.fit;
    const char* unit = allan_value_unit(input, c);
    if (fit.terms.empty()) text += "no warm-up found";
    for (std::size_t k = 0; k < fit.terms.size(); ++k) {
      const thermal::WarmUpTerm& term = fit.terms[k];
      std::snprintf(line, sizeof line, "%s%.3g +- %.2g %s, T %.4g +- %.2g s", k == 0 ? "" : "; ", term.amplitude,
                    term.amplitude_sigma, unit, term.time_constant_s, term.time_constant_sigma_s);
      text += line;
    }
    std::snprintf(line, sizeof line, "; trend after removal %.3g +- %.2g %s/s\n", fit.trend.slope_per_s,
                  fit.trend.slope_sigma_per_s, unit);
    text += line;
  }
  return text;
}

}  // namespace pipeline
}  // namespace imu_lab
