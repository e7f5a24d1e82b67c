// Correlation of a triad's three axes' noise (Krobka 2015 eq. 2.36 at equal times, normalised): the sample
// correlation matrix of the axes' samples, each axis's mean removed, at tau0 and of the means of
// non-overlapping blocks of m samples (the noise after averaging over m tau0). Correlated white
// noise keeps its matrix under averaging; noise whose low-frequency part is correlated
// differently shows a matrix that changes with m.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace imu_lab {
namespace spectrum {

struct AxisCorrelation {
  std::size_t averaging_factor = 1;  // m
  double averaging_time_s = 0.0;     // m tau0
  std::size_t block_count = 0;       // n = floor(samples / m)
  double confidence = 0.0;
  Eigen::Matrix3d correlation = Eigen::Matrix3d::Identity();
  // Fisher's z interval of each off-diagonal entry: tanh(atanh(r) -+ z_q / sqrt(n_eff - 3)), q =
  // (1 + confidence) / 2 (Fisher 1921), for jointly normal block means. Block means that follow
  // each other in time (a sensor's front-end filter, bias instability, a spectral line) carry
  // fewer independent values than n; the pair's effective count replaces n (Pyper & Peterman
  // 1998 eq. 1, after Bartlett 1935):
  //   1 / n_eff = 1 / n + (2 / n) sum_{j=1}^{n/5} r_a(j) r_b(j),
  // r_a, r_b the two axes' sample autocorrelations of the block means (autocorrelation.h: the
  // biased estimator, whose taper stands for their (n - j) / n weight); n_eff is kept within
  // at most n, and an n_eff of 3 or less gives the whole [-1, 1]. The diagonal is exactly 1.
  Eigen::Matrix3d lower = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d upper = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d effective_block_count = Eigen::Matrix3d::Zero();  // n_eff per pair; n on the diagonal
  // Each axis's lag-1 autocorrelation of the block means, and the band white noise keeps it in
  // (autocorrelation.h): outside it the block means are correlated in time and n_eff < n.
  Eigen::Vector3d block_lag1_autocorrelation = Eigen::Vector3d::Zero();
  double white_band = 0.0;
  bool blocks_look_independent() const;
};

// The smallest block count accepted: Fisher's approximation needs n well above 3.
constexpr std::size_t kMinimumCorrelationBlocks = 10;

// Throws InputError (common/config_error.h) naming the factor when it leaves fewer than
// kMinimumCorrelationBlocks blocks or is 0, naming the axis when an axis does not vary, and for
// values that are not finite; std::invalid_argument unless 0 < confidence < 1.
AxisCorrelation axis_correlation(const std::vector<Eigen::Vector3d>& samples, double tau0_s,
                                 std::size_t averaging_factor, double confidence);

}  // namespace spectrum
}  // namespace imu_lab
