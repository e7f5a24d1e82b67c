#include "imu_lab/spectrum/welch.h"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace spectrum {
namespace {
constexpr double kPi = 3.14159265358979323846;
// Correlation of neighbouring Hann-windowed segments at 50 % overlap (Welch 1967, table 1).
constexpr double kHannHalfOverlapCorrelation = 0.167;
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
  double window_power = 0.0;
  for (std::size_t k = 0; k < length; ++k) {
    window[k] = 0.5 * (1.0 - std::cos(2.0 * kPi * static_cast<double>(k) / static_cast<double>(length)));
    window_power += window[k] * window[k];
  }
  const std::size_t bins = length / 2 + 1;
  PowerSpectrum spectrum;
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
  spectrum.frequency_hz.resize(bins);
  for (std::size_t bin = 0; bin < bins; ++bin) {
    const bool edge = bin == 0 || 2 * bin == length;
    spectrum.density[bin] *= scale * (edge ? 1.0 : 2.0);
    spectrum.frequency_hz[bin] = static_cast<double>(bin) * spectrum.resolution_hz;
  }
  spectrum.degrees_of_freedom = 2.0 * static_cast<double>(spectrum.segment_count) /
                                (1.0 + 2.0 * kHannHalfOverlapCorrelation * kHannHalfOverlapCorrelation);
  return spectrum;
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
