#include "imu_lab/thermal/orientation_clusters.h"

#include <cmath>

namespace imu_lab {
namespace thermal {
namespace {

Eigen::Vector3d earth_rate_in_body(const Eigen::Vector3d& up, const Eigen::Vector3d& mean_rate,
                                   const EarthReference& earth) {
  const Eigen::Vector3d vertical = earth.earth_rate_rad_s * std::sin(earth.latitude_rad) * up;
  const Eigen::Vector3d measured_horizontal = mean_rate - mean_rate.dot(up) * up;
  const double horizontal_norm = measured_horizontal.norm();
  if (horizontal_norm == 0.0) return vertical;
  return vertical + earth.earth_rate_rad_s * std::cos(earth.latitude_rad) * measured_horizontal / horizontal_norm;
}

}  // namespace

OrientationAssignment cluster_by_gravity(const std::vector<ThermalWindow>& windows, double max_angle_rad,
                                         const EarthReference& earth) {
  OrientationAssignment out;
  out.cluster_of_window.assign(windows.size(), -1);
  std::vector<Eigen::Vector3d> force_sums, rate_sums;
  const double min_cosine = std::cos(max_angle_rad);
  for (std::size_t w = 0; w < windows.size(); ++w) {
    if (!windows[w].is_static) continue;
    const Eigen::Vector3d direction = windows[w].mean_specific_force_m_s2.normalized();
    int chosen = -1;
    for (std::size_t c = 0; c < force_sums.size() && chosen < 0; ++c) {
      if (force_sums[c].normalized().dot(direction) >= min_cosine) chosen = static_cast<int>(c);
    }
    if (chosen < 0) {
      chosen = static_cast<int>(force_sums.size());
      force_sums.push_back(Eigen::Vector3d::Zero());
      rate_sums.push_back(Eigen::Vector3d::Zero());
      out.clusters.emplace_back();
    }
    force_sums[chosen] += windows[w].mean_specific_force_m_s2;
    rate_sums[chosen] += windows[w].mean_angular_rate_rad_s;
    ++out.clusters[chosen].window_count;
    out.cluster_of_window[w] = chosen;
  }
  for (std::size_t c = 0; c < out.clusters.size(); ++c) {
    OrientationCluster& cluster = out.clusters[c];
    cluster.up_body = force_sums[c].normalized();
    cluster.specific_force_input_m_s2 = earth.gravity_m_s2 * cluster.up_body;
    cluster.angular_rate_input_rad_s = earth_rate_in_body(cluster.up_body, rate_sums[c] / cluster.window_count, earth);
  }
  return out;
}

}  // namespace thermal
}  // namespace imu_lab
