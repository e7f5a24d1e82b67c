// What each static interval (rest) measured: mean rate and specific force, and how uncertain
// those means are. The noise comes from the scatter of short block means inside the rests, pooled
// over all rests, so coloured noise (anti-alias filters, quantization) is counted as it averages;
// drift at the rest's own scale (bias instability, random walk) is added where the halves of the
// rests differ by significantly more than that white figure says.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "imu_lab/calib/static_intervals.h"

namespace imu_lab {
namespace calib {

struct RestMeans {
  StaticInterval interval;
  double start_s = 0.0;
  double duration_s = 0.0;
  Eigen::Vector3d mean_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_force_m_s2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d rate_sigma_of_mean_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_sigma_of_mean_m_s2 = Eigen::Vector3d::Zero();
};

struct RestStatistics {
  std::vector<RestMeans> rests;
  double block_s = 0.0;
  // White-noise densities implied by the block means (continuous time, per sqrt(Hz)).
  Eigen::Vector3d rate_density_rad_s_per_sqrt_hz = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_density_m_s2_per_sqrt_hz = Eigen::Vector3d::Zero();
};

// block_s: length of the blocks; rests shorter than two blocks contribute no noise estimate.
RestStatistics rest_statistics(const std::vector<io::ImuRecord>& samples, const std::vector<StaticInterval>& intervals,
                               double block_s);

}  // namespace calib
}  // namespace imu_lab
