#include "imu_lab/spectrum/spectrum_report.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/format_number.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/repeatability/lot.h"
#include "imu_lab/spectrum/autocorrelation.h"
#include "imu_lab/spectrum/model_spectrum.h"

namespace imu_lab {
namespace spectrum {
namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z"};

struct Triad {
  const char* name;
  const char* unit;
  Eigen::Vector3d io::ImuRecord::*values;
};
constexpr Triad kTriads[] = {{"gyro", "rad_s", &io::ImuRecord::angular_rate_rad_s},
                             {"accelerometer", "m_s2", &io::ImuRecord::specific_force_m_s2}};

std::string squared_unit(const std::string& unit) { return unit == "rad_s" ? "rad2_s2" : "m2_s4"; }

void emit_matrix(YAML::Emitter& out, const char* key, const Eigen::Matrix3d& matrix) {
  out << YAML::Key << key << YAML::Value << YAML::BeginSeq;
  for (int row = 0; row < 3; ++row) {
    out << YAML::Flow << YAML::BeginSeq;
    for (int column = 0; column < 3; ++column) out << matrix(row, column);
    out << YAML::EndSeq;
  }
  out << YAML::EndSeq;
}

}  // namespace

double uniform_sample_interval_s(const std::vector<double>& stamps_s, double tolerance) {
  if (stamps_s.size() < 2) throw InputError("spectrum: fewer than two samples");
  const double tau0_s = (stamps_s.back() - stamps_s.front()) / static_cast<double>(stamps_s.size() - 1);
  for (std::size_t k = 1; k < stamps_s.size(); ++k) {
    const double interval_s = stamps_s[k] - stamps_s[k - 1];
    if (std::abs(interval_s - tau0_s) > tolerance * tau0_s) {
      throw InputError("spectrum: the interval " + format_number(interval_s, 4) + " s at " +
                       format_number(stamps_s[k] - stamps_s.front(), 6) + " s after the first stamp is not tau0 " +
                       format_number(tau0_s, 6) +
                       " s (a gap or a repeated stamp); spectra need uniform "
                       "sampling: choose a window without it (--start-s, --end-s)");
    }
  }
  return tau0_s;
}

SpectrumAnalysis analyse_spectra(const std::vector<io::ImuRecord>& samples, const SpectrumOptions& options) {
  SpectrumAnalysis analysis;
  std::vector<double> stamps(samples.size());
  std::transform(samples.begin(), samples.end(), stamps.begin(),
                 [](const io::ImuRecord& s) { return seconds_from_stamp_ns(s.stamp_ns); });
  analysis.tau0_s = uniform_sample_interval_s(stamps, options.interval_tolerance);
  analysis.sample_count = samples.size();
  analysis.confidence = options.confidence;
  analysis.autocorrelation_band = white_noise_band(samples.size(), options.confidence);
  const auto max_lag = static_cast<std::size_t>(std::llround(options.max_lag_s / analysis.tau0_s));
  for (const Triad& triad : kTriads) {
    std::vector<Eigen::Vector3d> values(samples.size());
    std::transform(samples.begin(), samples.end(), values.begin(),
                   [&](const io::ImuRecord& s) { return s.*triad.values; });
    for (int axis = 0; axis < 3; ++axis) {
      ChannelSpectrum channel;
      channel.name = std::string(triad.name) + "_" + kAxisNames[axis];
      channel.unit = triad.unit;
      std::vector<double> axis_values(values.size());
      std::transform(values.begin(), values.end(), axis_values.begin(),
                     [&](const Eigen::Vector3d& v) { return v[axis]; });
      try {
        channel.psd = welch_psd(axis_values, analysis.tau0_s, options.welch);
        channel.autocorrelation = autocorrelation(axis_values, max_lag);
      } catch (const InputError& error) {
        throw InputError(channel.name + ": " + error.what());
      }
      analysis.channels.push_back(std::move(channel));
    }
    TriadCorrelation correlation{triad.name, {}};
    for (std::size_t factor : options.averaging_factors) {
      try {
        correlation.by_factor.push_back(axis_correlation(values, analysis.tau0_s, factor, options.confidence));
      } catch (const InputError& error) {
        throw InputError(std::string(triad.name) + ": " + error.what());
      }
    }
    analysis.triads.push_back(std::move(correlation));
  }
  return analysis;
}

std::vector<std::string> overlay_noise_models(SpectrumAnalysis& analysis,
                                              const std::map<std::string, double>& noise_report_values) {
  // A lot of one unit: typical_model's medians are that unit's own values.
  const std::vector<repeatability::LotUnit> report{{"model", noise_report_values}};
  std::vector<std::string> drawn;
  for (ChannelSpectrum& channel : analysis.channels) {
    std::string report_channel = channel.name;
    if (report_channel.rfind("accelerometer_", 0) == 0) report_channel = "accel_" + report_channel.substr(14);
    const identify::NoiseModel model = repeatability::typical_model(report, report_channel);
    if (model.terms.empty()) continue;
    channel.model_density = model_density(model, channel.psd, analysis.tau0_s);
    channel.model_has_rate_ramp = std::any_of(model.terms.begin(), model.terms.end(), [](const identify::Term& t) {
      return t.kind == identify::TermKind::kRateRamp;
    });
    drawn.push_back(channel.name);
  }
  return drawn;
}

std::string psd_csv(const SpectrumAnalysis& analysis) {
  std::string text = "frequency_hz,degrees_of_freedom";
  for (const ChannelSpectrum& c : analysis.channels) {
    const std::string column = c.name + "_psd_" + squared_unit(c.unit) + "_per_hz";
    text += "," + column + "," + column + "_lower," + column + "_upper";
    if (!c.model_density.empty()) text += "," + c.name + "_model_psd_" + squared_unit(c.unit) + "_per_hz";
  }
  text += "\n";
  const PowerSpectrum& first = analysis.channels.front().psd;
  for (std::size_t bin = 1; bin < first.density.size(); ++bin) {
    text += format_number(first.frequency_hz[bin]) + "," + format_number(bin_degrees_of_freedom(first, bin));
    for (const ChannelSpectrum& c : analysis.channels) {
      const DensityInterval interval = density_interval(c.psd, bin, analysis.confidence);
      text += "," + format_number(c.psd.density[bin]) + "," + format_number(interval.lower) + "," +
              format_number(interval.upper);
      if (!c.model_density.empty()) text += "," + format_number(c.model_density[bin]);
    }
    text += "\n";
  }
  return text;
}

std::string autocorrelation_csv(const SpectrumAnalysis& analysis) {
  std::string text = "lag_s,white_band";
  for (const ChannelSpectrum& c : analysis.channels) text += "," + c.name;
  text += "\n";
  const std::size_t lags = analysis.channels.front().autocorrelation.size();
  for (std::size_t k = 0; k < lags; ++k) {
    text +=
        format_number(static_cast<double>(k) * analysis.tau0_s) + "," + format_number(analysis.autocorrelation_band);
    for (const ChannelSpectrum& c : analysis.channels) text += "," + format_number(c.autocorrelation[k]);
    text += "\n";
  }
  return text;
}

std::string correlation_yaml(const SpectrumAnalysis& analysis, const std::string& recording_name) {
  const PowerSpectrum& first = analysis.channels.front().psd;
  YAML::Emitter out;
  out.SetDoublePrecision(kRoundTripDigits);
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << "imu_lab_spectrum";
  out << YAML::Key << "recording" << YAML::Value << recording_name;
  out << YAML::Key << "samples" << YAML::Value << analysis.sample_count;
  out << YAML::Key << "tau0_s" << YAML::Value << analysis.tau0_s;
  out << YAML::Key << "confidence" << YAML::Value << analysis.confidence;
  out << YAML::Key << "welch" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "window" << YAML::Value << "hann, 50 % overlap, each segment's mean removed";
  out << YAML::Key << "segment_length" << YAML::Value << first.segment_length;
  out << YAML::Key << "segment_count" << YAML::Value << first.segment_count;
  out << YAML::Key << "resolution_hz" << YAML::Value << first.resolution_hz;
  out << YAML::Key << "degrees_of_freedom" << YAML::Value << first.degrees_of_freedom;
  // The interval is the same multiple of every bin's estimate (away from DC and Nyquist).
  const DensityInterval factors = interval_factors(first.degrees_of_freedom, analysis.confidence);
  out << YAML::Key << "interval_factors" << YAML::Value << YAML::Flow << YAML::BeginSeq << factors.lower
      << factors.upper << YAML::EndSeq;
  out << YAML::EndMap;
  out << YAML::Key << "autocorrelation_white_band" << YAML::Value << analysis.autocorrelation_band;
  out << YAML::Key << "axis_correlation" << YAML::Value << YAML::BeginMap;
  for (const TriadCorrelation& triad : analysis.triads) {
    out << YAML::Key << triad.triad << YAML::Value << YAML::BeginSeq;
    for (const AxisCorrelation& c : triad.by_factor) {
      out << YAML::BeginMap;
      out << YAML::Key << "averaging_factor" << YAML::Value << c.averaging_factor;
      out << YAML::Key << "averaging_time_s" << YAML::Value << c.averaging_time_s;
      out << YAML::Key << "blocks" << YAML::Value << c.block_count;
      emit_matrix(out, "correlation", c.correlation);
      emit_matrix(out, "lower", c.lower);
      emit_matrix(out, "upper", c.upper);
      emit_matrix(out, "effective_block_count", c.effective_block_count);
      out << YAML::Key << "block_lag1_autocorrelation" << YAML::Value << YAML::Flow << YAML::BeginSeq
          << c.block_lag1_autocorrelation.x() << c.block_lag1_autocorrelation.y() << c.block_lag1_autocorrelation.z()
          << YAML::EndSeq;
      out << YAML::Key << "white_band" << YAML::Value << c.white_band;
      out << YAML::Key << "blocks_look_independent" << YAML::Value << c.blocks_look_independent();
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

namespace {

// The interval of block means that follow each other is widened to their effective count
// (axis_correlation.h); the line says so, with the smallest count of the three pairs.
std::string correlated_in_time_note(const AxisCorrelation& c) {
  const double fewest =
      std::min({c.effective_block_count(0, 1), c.effective_block_count(0, 2), c.effective_block_count(1, 2)});
  return ", widened: the block means are correlated in time, ~" + format_printf(fewest, "%.4g") + " independent of " +
         std::to_string(c.block_count) + ")";
}

}  // namespace

std::string spectrum_summary(const SpectrumAnalysis& analysis) {
  const PowerSpectrum& first = analysis.channels.front().psd;
  std::string text = std::to_string(analysis.sample_count) + " samples, tau0 " +
                     format_printf(analysis.tau0_s, "%.6g") + " s; Welch: " + std::to_string(first.segment_count) +
                     " segments of " + std::to_string(first.segment_length) + ", resolution " +
                     format_printf(first.resolution_hz, "%.4g") + " Hz, " +
                     format_printf(first.degrees_of_freedom, "%.1f") + " degrees of freedom per bin\n";
  for (const ChannelSpectrum& channel : analysis.channels) {
    if (channel.model_density.empty()) continue;
    // The model's share of the estimate: the median ratio over the bins (1 where they agree).
    std::vector<double> ratios;
    for (std::size_t bin = 1; bin < channel.model_density.size(); ++bin) {
      if (channel.model_density[bin] > 0.0) ratios.push_back(channel.psd.density[bin] / channel.model_density[bin]);
    }
    std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
    text += channel.name + " model drawn: estimate / model median " +
            format_printf(ratios.empty() ? 0.0 : ratios[ratios.size() / 2], "%.3g") +
            (channel.model_has_rate_ramp ? " (its rate ramp left out: no stationary PSD)" : "") + "\n";
  }
  for (const TriadCorrelation& triad : analysis.triads) {
    for (const AxisCorrelation& c : triad.by_factor) {
      text += triad.triad + " axis correlation at " + format_printf(c.averaging_time_s, "%.4g") + " s: xy " +
              format_printf(c.correlation(0, 1), "%+.3f") + " xz " + format_printf(c.correlation(0, 2), "%+.3f") +
              " yz " + format_printf(c.correlation(1, 2), "%+.3f") + " (" +
              format_printf(100.0 * analysis.confidence, "%.3g") + " % half-width ~" +
              format_printf(0.5 * (c.upper(0, 1) - c.lower(0, 1)), "%.2g") +
              (c.blocks_look_independent() ? std::string(")") : correlated_in_time_note(c)) + "\n";
    }
  }
  return text;
}

}  // namespace spectrum
}  // namespace imu_lab
