#include "imu_lab/spectrum/welch.h"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/allan/confidence.h"

namespace imu_lab {
namespace spectrum {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

PowerSpectrum welch_psd(const std::vector<double>& values, double tau0_s, const WelchOptions& options) {
  const std::size_t length = options.segment_length;
  if (!(tau0_s > 0.0) || !std::isfinite(tau0_s)) {
    throw InputError("Welch PSD: the sample interval must be positive and finite, not " + std::to_string(tau0_s));
  }
  if (length < 8) throw InputError("Welch PSD: a segment needs at least 8 samples, not " + std::to_string(length));
  if (values.size() < length) {
    throw InputError("Welch PSD: " + std::to_string(values.size()) + " samples, fewer than one segment of " +
                     std::to_string(length));
  }
  if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) {
    throw InputError("Welch PSD: the record holds values that are not finite");
  }
  std::vector<double> window(length);
  double window_power = 0.0, window_sum = 0.0;
  for (std::size_t k = 0; k < length; ++k) {
    window[k] = 0.5 * (1.0 - std::cos(2.0 * kPi * static_cast<double>(k) / static_cast<double>(length)));
    window_power += window[k] * window[k];
    window_sum += window[k];
  }
  const std::size_t bins = length / 2 + 1;
  PowerSpectrum spectrum;
  spectrum.segment_length = length;
  spectrum.density.assign(bins, 0.0);
  Eigen::FFT<double> fft;
  std::vector<double> segment(length);
  std::vector<std::complex<double>> transform;
  const std::size_t hop = length / 2;
  for (std::size_t start = 0; start + length <= values.size(); start += hop) {
    double mean = 0.0;
    for (std::size_t k = 0; k < length; ++k) mean += values[start + k];
    mean /= static_cast<double>(length);
    for (std::size_t k = 0; k < length; ++k) segment[k] = (values[start + k] - mean) * window[k];
    fft.fwd(transform, segment);
    for (std::size_t bin = 0; bin < bins; ++bin) spectrum.density[bin] += std::norm(transform[bin]);
    ++spectrum.segment_count;
  }
  // Periodogram |X|^2 tau0 / sum(w^2) is the two-sided density; doubled except at 0 and Nyquist.
  const double scale = tau0_s / (window_power * static_cast<double>(spectrum.segment_count));
  spectrum.resolution_hz = 1.0 / (static_cast<double>(length) * tau0_s);
  spectrum.equivalent_noise_bandwidth_hz =
      static_cast<double>(length) * window_power / (window_sum * window_sum) * spectrum.resolution_hz;
  spectrum.frequency_hz.resize(bins);
  for (std::size_t bin = 0; bin < bins; ++bin) {
    const bool edge = bin == 0 || 2 * bin == length;
    spectrum.density[bin] *= scale * (edge ? 1.0 : 2.0);
    spectrum.frequency_hz[bin] = static_cast<double>(bin) * spectrum.resolution_hz;
  }
  double overlap_sum = 0.0;
  for (std::size_t k = 0; k + hop < length; ++k) overlap_sum += window[k] * window[k + hop];
  const double neighbour_correlation = overlap_sum / window_power;
  const double segments = static_cast<double>(spectrum.segment_count);
  spectrum.degrees_of_freedom =
      2.0 * segments / (1.0 + 2.0 * (1.0 - 1.0 / segments) * neighbour_correlation * neighbour_correlation);
  return spectrum;
}

double bin_degrees_of_freedom(const PowerSpectrum& spectrum, std::size_t bin) {
  if (bin == 0) return 0.0;
  return 2 * bin == spectrum.segment_length ? 0.5 * spectrum.degrees_of_freedom : spectrum.degrees_of_freedom;
}

DensityInterval interval_factors(double degrees_of_freedom, double confidence) {
  // A density is a variance: the bounds of its square root (NIST SP 1065 eq. 45), squared.
  const allan::DeviationBounds bounds = allan::chi_squared_bounds(1.0, degrees_of_freedom, confidence);
  return {bounds.lower * bounds.lower, bounds.upper * bounds.upper};
}

DensityInterval density_interval(const PowerSpectrum& spectrum, std::size_t bin, double confidence) {
  const double dof = bin_degrees_of_freedom(spectrum, bin);
  if (!(dof > 0.0)) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  const DensityInterval factors = interval_factors(dof, confidence);
  return {factors.lower * spectrum.density[bin], factors.upper * spectrum.density[bin]};
}

double median_density(const PowerSpectrum& spectrum, double low_hz, double high_hz) {
  std::vector<double> inside;
  for (std::size_t bin = 0; bin < spectrum.density.size(); ++bin) {
    if (spectrum.frequency_hz[bin] >= low_hz && spectrum.frequency_hz[bin] <= high_hz) {
      inside.push_back(spectrum.density[bin]);
    }
  }
  if (inside.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t middle = inside.size() / 2;
  std::nth_element(inside.begin(), inside.begin() + middle, inside.end());
  if (inside.size() % 2 == 1) return inside[middle];
  const double upper = inside[middle];
  return 0.5 * (upper + *std::max_element(inside.begin(), inside.begin() + middle));
}

}  // namespace spectrum
}  // namespace imu_lab
