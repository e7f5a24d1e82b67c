#include "imu_lab/spectrum/autocorrelation.h"

#include <unsupported/Eigen/FFT>

#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace spectrum {

std::vector<double> autocorrelation(const std::vector<double>& values, std::size_t max_lag) {
  const std::size_t n = values.size();
  if (n < max_lag + 2) {
    throw InputError("autocorrelation: " + std::to_string(n) + " samples, too few for lags up to " +
                     std::to_string(max_lag));
  }
  if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) {
    throw InputError("autocorrelation: the record holds values that are not finite");
  }
  // Exactly equal values, not a zero sum of squares: rounding leaves a constant a tiny one.
  if (std::all_of(values.begin(), values.end(), [&](double v) { return v == values.front(); })) {
    throw InputError("autocorrelation: the record has no variance (all values equal)");
  }
  double mean = 0.0;
  for (double v : values) mean += v;
  mean /= static_cast<double>(n);
  // Padding to at least n + max_lag keeps the circular correlation free of wrap-around.
  std::size_t padded = 1;
  while (padded < n + max_lag) padded *= 2;
  std::vector<double> centred(padded, 0.0);
  for (std::size_t t = 0; t < n; ++t) centred[t] = values[t] - mean;
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> transform;
  fft.fwd(transform, centred);
  for (auto& value : transform) value = std::norm(value);
  std::vector<double> sums;
  fft.inv(sums, transform);
  std::vector<double> r(max_lag + 1);
  for (std::size_t k = 0; k <= max_lag; ++k) r[k] = sums[k] / sums[0];
  return r;
}

double white_noise_band(std::size_t sample_count, double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw std::invalid_argument("white_noise_band: confidence " + std::to_string(confidence) +
                                " must lie strictly between 0 and 1");
  }
  const double z = boost::math::quantile(boost::math::normal_distribution<double>(), 0.5 * (1.0 + confidence));
  return z / std::sqrt(static_cast<double>(sample_count));
}

}  // namespace spectrum
}  // namespace imu_lab
