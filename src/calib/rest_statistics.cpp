#include "imu_lab/calib/rest_statistics.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace calib {
namespace {

struct PooledVariance {
  Eigen::Vector3d sum_squares = Eigen::Vector3d::Zero();
  double degrees_of_freedom = 0.0;
  Eigen::Vector3d variance() const { return sum_squares / std::max(1.0, degrees_of_freedom); }
};

template <class Get>
Eigen::Vector3d mean_over(const std::vector<io::ImuRecord>& samples, std::size_t begin, std::size_t end, Get get) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t k = begin; k < end; ++k) sum += get(samples[k]);
  return sum / static_cast<double>(end - begin);
}

// The block scatter sees noise at the block's scale only; bias instability (flicker) or a random
// walk moves a rest's mean by more than white noise averaged over the rest would (a navigation-grade
// accelerometer: 5 ug of instability against 0.9 ug of white noise over 60 s). The difference of
// the two halves of a rest sees the noise at half the rest's length: its variance / 4 is the
// variance of the rest's mean for white noise (then it matches the white figure) and about the
// Allan variance at T/2 otherwise. Pooled over the rests, an excess over the white figure beyond
// the 95 % chi-squared quantile of its degrees of freedom is added to every rest's sigma, so a pure
// white-noise recording keeps its white sigmas.
template <class Get, class Sigma>
void add_drift_at_the_rest_scale(const std::vector<io::ImuRecord>& samples, RestStatistics& statistics, Get get,
                                 Sigma sigma_of) {
  Eigen::Vector3d observed = Eigen::Vector3d::Zero(), white = Eigen::Vector3d::Zero();
  double rests = 0.0;
  for (RestMeans& rest : statistics.rests) {
    const std::size_t half = rest.interval.size() / 2;
    if (half < 2) continue;
    const Eigen::Vector3d difference = mean_over(samples, rest.interval.begin, rest.interval.begin + half, get) -
                                       mean_over(samples, rest.interval.begin + half, rest.interval.end, get);
    observed += difference.cwiseAbs2() / 4.0;
    white += sigma_of(rest).cwiseAbs2();
    rests += 1.0;
  }
  if (rests < 2.0) return;
  observed /= rests;
  white /= rests;
  const double significant = boost::math::quantile(boost::math::chi_squared(rests), 0.95) / rests;
  for (int axis = 0; axis < 3; ++axis) {
    if (!(observed[axis] > significant * white[axis])) continue;
    const double excess = observed[axis] - white[axis];
    for (RestMeans& rest : statistics.rests) {
      double& sigma = sigma_of(rest)[axis];
      sigma = std::sqrt(sigma * sigma + excess);
    }
  }
}

}  // namespace

RestStatistics rest_statistics(const std::vector<io::ImuRecord>& samples, const std::vector<StaticInterval>& intervals,
                               double block_s) {
  if (samples.size() < 2 || intervals.empty()) throw InputError("calibration recording: no static intervals");
  const double sample_interval_s =
      seconds_between(samples.front().stamp_ns, samples.back().stamp_ns) / (samples.size() - 1);
  const std::size_t block = std::max<std::size_t>(1, std::lround(block_s / sample_interval_s));
  const auto rate = [](const io::ImuRecord& s) { return s.angular_rate_rad_s; };
  const auto force = [](const io::ImuRecord& s) { return s.specific_force_m_s2; };

  RestStatistics statistics;
  statistics.block_s = block * sample_interval_s;
  PooledVariance rate_blocks, force_blocks;
  for (const StaticInterval& interval : intervals) {
    RestMeans rest;
    rest.interval = interval;
    rest.start_s = seconds_from_stamp_ns(samples[interval.begin].stamp_ns);
    rest.duration_s = interval.size() * sample_interval_s;
    rest.mean_rate_rad_s = mean_over(samples, interval.begin, interval.end, rate);
    rest.mean_force_m_s2 = mean_over(samples, interval.begin, interval.end, force);
    const std::size_t blocks = interval.size() / block;
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t first = interval.begin + b * block;
      rate_blocks.sum_squares += (mean_over(samples, first, first + block, rate) - rest.mean_rate_rad_s).cwiseAbs2();
      force_blocks.sum_squares += (mean_over(samples, first, first + block, force) - rest.mean_force_m_s2).cwiseAbs2();
    }
    if (blocks >= 2) {
      rate_blocks.degrees_of_freedom += blocks - 1;
      force_blocks.degrees_of_freedom += blocks - 1;
    }
    statistics.rests.push_back(rest);
  }
  if (rate_blocks.degrees_of_freedom < 1.0) {
    throw InputError("calibration recording: the rests are too short (under two " + std::to_string(statistics.block_s) +
                     " s blocks) to measure the noise; dwell longer");
  }
  const Eigen::Vector3d rate_block_sigma = rate_blocks.variance().cwiseSqrt();
  const Eigen::Vector3d force_block_sigma = force_blocks.variance().cwiseSqrt();
  statistics.rate_density_rad_s_per_sqrt_hz = rate_block_sigma * std::sqrt(statistics.block_s);
  statistics.force_density_m_s2_per_sqrt_hz = force_block_sigma * std::sqrt(statistics.block_s);
  for (RestMeans& rest : statistics.rests) {
    const double shrink = std::sqrt(static_cast<double>(block) / rest.interval.size());
    rest.rate_sigma_of_mean_rad_s = rate_block_sigma * shrink;
    rest.force_sigma_of_mean_m_s2 = force_block_sigma * shrink;
  }
  add_drift_at_the_rest_scale(samples, statistics, rate,
                              [](RestMeans& rest) -> Eigen::Vector3d& { return rest.rate_sigma_of_mean_rad_s; });
  add_drift_at_the_rest_scale(samples, statistics, force,
                              [](RestMeans& rest) -> Eigen::Vector3d& { return rest.force_sigma_of_mean_m_s2; });
  return statistics;
}

}  // namespace calib
}  // namespace imu_lab
