// The spectrum tool's analysis of a static recording (doc/spectrum.md): per channel (gyro x, y, z,
// accelerometer x, y, z) Welch's PSD with its chi-squared interval and the autocorrelation; per
// triad the axes' correlation matrix at tau0 and after averaging. Its files: the PSDs and the
// autocorrelations as CSV (one column per channel), the correlation matrices and the analysis
// settings (resolution, segments, degrees of freedom) as YAML.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "imu_lab/io/imu_records.h"
#include "imu_lab/spectrum/axis_correlation.h"
#include "imu_lab/spectrum/welch.h"

namespace imu_lab {
namespace spectrum {

struct SpectrumOptions {
  WelchOptions welch;
  double max_lag_s = 10.0;
  std::vector<std::size_t> averaging_factors{1, 10, 100};
  double confidence = 0.95;
  // Spectra need uniform sampling: an interval further than this fraction of tau0 from it
  // refuses the record.
  double interval_tolerance = 0.5;
};

struct ChannelSpectrum {
  std::string name;  // "gyro_x" .. "accelerometer_z"
  std::string unit;  // of the values: "rad_s" or "m_s2"
  PowerSpectrum psd;
  std::vector<double> autocorrelation;  // lags 0 .. max_lag
  // The identified noise model's density over the estimate, per bin (model_spectrum.h); empty
  // without a model for this channel.
  std::vector<double> model_density;
  bool model_has_rate_ramp = false;  // left out of model_density (no stationary PSD)
};

struct TriadCorrelation {
  std::string triad;  // "gyro", "accelerometer"
  std::vector<AxisCorrelation> by_factor;
};

struct SpectrumAnalysis {
  double tau0_s = 0.0;
  std::size_t sample_count = 0;
  double confidence = 0.0;
  double autocorrelation_band = 0.0;  // white_noise_band(sample_count, confidence)
  std::vector<ChannelSpectrum> channels;
  std::vector<TriadCorrelation> triads;
};

// tau0 = the mean stamp interval. Throws InputError naming the first interval outside the
// tolerance (a gap or a repeated stamp) and its time from the first stamp; fewer than 2 stamps too.
double uniform_sample_interval_s(const std::vector<double>& stamps_s, double tolerance);

// Throws InputError for a record the analysis cannot use (too short for a segment, a lag or a
// factor; a channel without variance; non-uniform stamps), naming what to change.
SpectrumAnalysis analyse_spectra(const std::vector<io::ImuRecord>& samples, const SpectrumOptions& options);

// Draws each channel's identified model over its estimate: the model of the channel
// (gyro_x .. accel_z in the report) in a noise report's values, as identify::
// read_noise_report_values gives them from the `allan` tool's noise.yaml (read as
// repeatability::typical_model reads a unit's report). A channel the report gives no terms for
// gets none. Returns the names of the channels that got one.
std::vector<std::string> overlay_noise_models(SpectrumAnalysis& analysis,
                                              const std::map<std::string, double>& noise_report_values);

// frequency_hz, degrees_of_freedom, then per channel <name>_psd_<unit^2>_per_hz, _lower, _upper
// (the confidence interval) and, where a model is drawn, <name>_model_psd_<unit^2>_per_hz (one-sided
// like the estimate); bins 1 .. Nyquist (DC carries no information once the mean is removed).
std::string psd_csv(const SpectrumAnalysis& analysis);
// lag_s, white_band, then one column per channel.
std::string autocorrelation_csv(const SpectrumAnalysis& analysis);
// Settings, per-channel PSD summary and the correlation matrices with their intervals.
std::string correlation_yaml(const SpectrumAnalysis& analysis, const std::string& recording_name);
// A few lines for the terminal.
std::string spectrum_summary(const SpectrumAnalysis& analysis);

}  // namespace spectrum
}  // namespace imu_lab
