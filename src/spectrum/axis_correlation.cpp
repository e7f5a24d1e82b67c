#include "imu_lab/spectrum/axis_correlation.h"

#include <boost/math/distributions/normal.hpp>

#include <algorithm>
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
  const double half_width =
      boost::math::quantile(boost::math::normal_distribution<double>(), 0.5 * (1.0 + confidence)) / std::sqrt(n - 3.0);
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      if (a == b) continue;
      const double z = std::atanh(std::min(1.0, std::max(-1.0, result.correlation(a, b))));
      result.lower(a, b) = std::tanh(z - half_width);
      result.upper(a, b) = std::tanh(z + half_width);
    }
    std::vector<double> axis(result.block_count);
    for (std::size_t b = 0; b < result.block_count; ++b) axis[b] = blocks[b][a];
    result.block_lag1_autocorrelation[a] = autocorrelation(axis, 1)[1];
  }
  result.white_band = white_noise_band(result.block_count, confidence);
  return result;
}

}  // namespace spectrum
}  // namespace imu_lab
