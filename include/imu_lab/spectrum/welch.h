// Welch's averaged periodogram (Welch 1967; NIST SP 1065 section 7): the record cut into
// segments of `segment_length` samples overlapping by half, each detrended by its mean and
// weighted by a Hann window, the periodograms averaged. One-sided power spectral density in
// u^2/Hz for a signal in u: white noise of variance s^2 sampled every tau0 has 2 s^2 tau0, so
// the white rate density N of the Allan variance (AVAR = N^2 / tau) is sqrt(PSD / 2).
#pragma once

#include <cstddef>
#include <vector>

namespace imu_lab {
namespace spectrum {

struct WelchOptions {
  std::size_t segment_length = 4096;  // samples per segment; a power of two is fastest
};

struct PowerSpectrum {
  std::vector<double> frequency_hz;  // k / (segment_length tau0), k = 0 .. segment_length / 2
  std::vector<double> density;       // one-sided PSD [u^2/Hz]
  std::size_t segment_length = 0;
  std::size_t segment_count = 0;
  double resolution_hz = 0.0;  // bin spacing 1 / (segment_length tau0)
  // The window's equivalent noise bandwidth, L sum(w^2) / (sum w)^2 bins (1.5 for Hann; Harris
  // 1978): a sinusoid of power P centred on a bin reads P / this there.
  double equivalent_noise_bandwidth_hz = 0.0;
  // Equivalent degrees of freedom of each bin away from 0 and Nyquist, for a spectrum that is
  // smooth over a few bins: 2 K / (1 + 2 (1 - 1/K) c^2) for K segments, c the correlation of
  // neighbouring windowed segments (sum of w_k w_(k+L/2) over sum of w_k^2: 1/6 for Hann at 50 %
  // overlap), Welch 1967, Percival & Walden 1993 eq. 292b: about 1.89 per segment.
  double degrees_of_freedom = 0.0;
};

// Degrees of freedom of one bin: degrees_of_freedom inside, half of it at Nyquist (a real
// value per segment), 0 at DC (each segment's mean is removed, so no interval applies there).
double bin_degrees_of_freedom(const PowerSpectrum& spectrum, std::size_t bin);

// Two-sided chi-squared confidence interval of the true density at one bin: nu P / chi2(nu, (1 +
// confidence) / 2) .. nu P / chi2(nu, (1 - confidence) / 2), nu = bin_degrees_of_freedom
// (Bendat & Piersol 2010 ch. 8). Both NaN at DC. Throws std::invalid_argument unless
// 0 < confidence < 1.
struct DensityInterval {
  double lower = 0.0;
  double upper = 0.0;
};
// The interval of an estimate of 1 with nu degrees of freedom: the factors every estimate with
// those degrees of freedom is multiplied by.
DensityInterval interval_factors(double degrees_of_freedom, double confidence);
DensityInterval density_interval(const PowerSpectrum& spectrum, std::size_t bin, double confidence);

// Throws InputError (common/config_error.h) naming the problem if tau0 is not positive, the
// segment length is below 8, or the record holds fewer samples than one segment. Values that
// are not finite are refused too: a spectrum has no gaps.
PowerSpectrum welch_psd(const std::vector<double>& values, double tau0_s, const WelchOptions& options = {});

// Median of the density over [low_hz, high_hz] (bins inside); NaN when no bin lies there.
double median_density(const PowerSpectrum& spectrum, double low_hz, double high_hz);

}  // namespace spectrum
}  // namespace imu_lab
