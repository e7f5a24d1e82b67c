// Sample autocorrelation of one channel (Box & Jenkins 1976 eq. 2.1.12): the record's mean
// removed, r(k) = c(k) / c(0) with c(k) = sum_t x_t x_(t+k) / n (the biased estimator, whose
// sequence is positive semi-definite), computed through a zero-padded FFT.
#pragma once

#include <cstddef>
#include <vector>

namespace imu_lab {
namespace spectrum {

// r(0) = 1 .. r(max_lag). Throws InputError (common/config_error.h) if the record holds fewer
// than max_lag + 2 samples, a value that is not finite, or no variance.
std::vector<double> autocorrelation(const std::vector<double>& values, std::size_t max_lag);

// Half-width of the band in which r(k), k > 0, of white noise lies with probability `confidence`:
// r(k) is then N(0, 1 / n) (Bartlett 1946), so z((1 + confidence) / 2) / sqrt(n). A lag outside
// it says the samples are not independent at that lag. Throws std::invalid_argument unless
// 0 < confidence < 1.
double white_noise_band(std::size_t sample_count, double confidence);

}  // namespace spectrum
}  // namespace imu_lab
