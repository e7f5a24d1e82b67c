// What a scenario tells the emulator: the true body angular rate and specific force integrated
// exactly over each sample interval, and the truth at any instant. Times are scenario times:
// seconds since the start of the run (the emulator adds its start_time_s to the stamps).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>

namespace imu_lab {
namespace emulator {

// Truth at one instant. Body frame x forward, y left, z up (REP-103/145); world ENU.
struct TruthState {
  double time_s = 0.0;
  Eigen::Quaterniond attitude_body_to_enu = Eigen::Quaterniond::Identity();
  Eigen::Vector3d angular_rate_body_rad_s = Eigen::Vector3d::Zero();   // inertial, in body axes
  Eigen::Vector3d specific_force_body_m_s2 = Eigen::Vector3d::Zero();  // in body axes
  double latitude_rad = 0.0;
  double longitude_rad = 0.0;
  double height_m = 0.0;  // above the ellipsoid (or sphere)
  Eigen::Vector3d velocity_enu_m_s = Eigen::Vector3d::Zero();
  double temperature_c = 0.0;
  double temperature_rate_c_s = 0.0;
  std::optional<double> second_temperature_c;  // a second, lagging thermosensor, if configured
};

// Exact integrals of the truth over [start_s, start_s + interval_s], in body axes.
struct TruthIncrement {
  Eigen::Vector3d delta_angle_rad = Eigen::Vector3d::Zero();     // integral of body rate
  Eigen::Vector3d delta_velocity_m_s = Eigen::Vector3d::Zero();  // integral of specific force
  double mean_temperature_c = 0.0;
  double mean_temperature_rate_c_s = 0.0;  // (T(end) - T(start)) / interval
  std::optional<double> mean_second_temperature_c;
};

class MotionSource {
 public:
  virtual ~MotionSource() = default;
  // Called with consecutive intervals; implementations may keep state between calls.
  virtual TruthIncrement increment(double start_s, double interval_s) = 0;
  virtual TruthState truth_at(double time_s) const = 0;
};

}  // namespace emulator
}  // namespace imu_lab
