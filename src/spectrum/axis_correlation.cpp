#include "imu_lab/spectrum/axis_correlation.h"

#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/spectrum/autocorrelation.h"

namespace imu_lab {
namespace spectrum {

bool AxisCorrelation::blocks_look_independent() const {
  return block_lag1_autocorrelation.cwiseAbs().maxCoeff() <= white_band;
}

AxisCorrelation axis_correlation(const std::vector<Eigen::Vector3d>& samples, double tau0_s,
                                 std::size_t averaging_factor, double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw std::invalid_argument("axis correlation: confidence " + std::to_string(confidence) +
                                " must lie strictly between 0 and 1");
  }
  const std::string factor_name = "averaging factor " + std::to_string(averaging_factor);
  if (averaging_factor == 0) throw InputError("axis correlation: an averaging factor must be at least 1");
  AxisCorrelation result;
  result.averaging_factor = averaging_factor;
  result.averaging_time_s = static_cast<double>(averaging_factor) * tau0_s;
  result.block_count = samples.size() / averaging_factor;
  result.confidence = confidence;
  if (result.block_count < kMinimumCorrelationBlocks) {
    throw InputError("axis correlation: " + factor_name + " leaves " + std::to_string(result.block_count) +
                     " blocks of " + std::to_string(samples.size()) + " samples, fewer than " +
                     std::to_string(kMinimumCorrelationBlocks));
  }
  std::vector<Eigen::Vector3d> blocks(result.block_count, Eigen::Vector3d::Zero());
  for (std::size_t b = 0; b < result.block_count; ++b) {
    for (std::size_t k = 0; k < averaging_factor; ++k) blocks[b] += samples[b * averaging_factor + k];
    blocks[b] /= static_cast<double>(averaging_factor);
    if (!blocks[b].allFinite()) throw InputError("axis correlation: the record holds values that are not finite");
  }
  const double n = static_cast<double>(result.block_count);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& block : blocks) mean += block / n;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& block : blocks) covariance += (block - mean) * (block - mean).transpose();
  for (int a = 0; a < 3; ++a) {
    // Exactly equal block means, not a zero sum of squares: rounding leaves a constant a tiny one.
    if (std::all_of(blocks.begin(), blocks.end(), [&](const Eigen::Vector3d& v) { return v[a] == blocks[0][a]; })) {
      throw InputError(std::string("axis correlation: axis ") + "xyz"[a] + " does not vary (" + factor_name + ")");
    }
  }
  for (int a = 0; a < 3; ++a) {
    for (int b = a + 1; b < 3; ++b) {
      result.correlation(a, b) = result.correlation(b, a) =
          covariance(a, b) / std::sqrt(covariance(a, a) * covariance(b, b));
    }
  }
  // Each axis's autocorrelation of the block means up to n / 5 lags (Pyper & Peterman's cut-off).
  const std::size_t max_lag = std::max<std::size_t>(1, result.block_count / 5);
  std::array<std::vector<double>, 3> axis_autocorrelation;
  for (int a = 0; a < 3; ++a) {
    std::vector<double> axis(result.block_count);
    for (std::size_t b = 0; b < result.block_count; ++b) axis[b] = blocks[b][a];
    axis_autocorrelation[a] = autocorrelation(axis, max_lag);
    result.block_lag1_autocorrelation[a] = axis_autocorrelation[a][1];
  }
  const double z_quantile = boost::math::quantile(boost::math::normal_distribution<double>(), 0.5 * (1.0 + confidence));
  result.effective_block_count.diagonal().setConstant(n);
  for (int a = 0; a < 3; ++a) {
    for (int b = a + 1; b < 3; ++b) {
      double lag_sum = 0.0;
      for (std::size_t j = 1; j <= max_lag; ++j) lag_sum += axis_autocorrelation[a][j] * axis_autocorrelation[b][j];
      const double inverse = (1.0 + 2.0 * lag_sum) / n;
      const double effective = inverse > 1.0 / n ? 1.0 / inverse : n;
      result.effective_block_count(a, b) = result.effective_block_count(b, a) = effective;
      const double z = std::atanh(std::min(1.0, std::max(-1.0, result.correlation(a, b))));
      const bool informative = effective > 3.0;
      const double half_width = informative ? z_quantile / std::sqrt(effective - 3.0) : 0.0;
      result.lower(a, b) = result.lower(b, a) = informative ? std::tanh(z - half_width) : -1.0;
      result.upper(a, b) = result.upper(b, a) = informative ? std::tanh(z + half_width) : 1.0;
    }
  }
  result.white_band = white_noise_band(result.block_count, confidence);
  return result;
}

}  // namespace spectrum
}  // namespace imu_lab
