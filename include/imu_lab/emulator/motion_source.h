// What a scenario tells the emulator: the true body angular rate and specific force integrated
// exactly over each sample interval, and the truth at any instant. Static is the first
// implementation; motion and thermal scenarios implement the same interface later.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

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
};

// Exact integrals of the truth over [start_s, start_s + interval_s], in body axes.
struct TruthIncrement {
  Eigen::Vector3d delta_angle_rad = Eigen::Vector3d::Zero();      // integral of body rate
  Eigen::Vector3d delta_velocity_m_s = Eigen::Vector3d::Zero();   // integral of specific force
  double mean_temperature_c = 0.0;
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
