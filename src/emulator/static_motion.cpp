#include "imu_lab/emulator/static_motion.h"

#include "imu_lab/emulator/earth_model.h"

namespace imu_lab {
namespace emulator {

Eigen::Quaterniond attitude_from_roll_pitch_yaw(double roll, double pitch, double yaw) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()));
}

StaticMotionSource::StaticMotionSource(const ScenarioConfig& scenario) {
  state_.attitude_body_to_enu = attitude_from_roll_pitch_yaw(scenario.roll_rad, scenario.pitch_rad, scenario.yaw_rad);
  const Eigen::Matrix3d enu_to_body = state_.attitude_body_to_enu.toRotationMatrix().transpose();
  const double gravity = normal_gravity_m_s2(scenario.earth_model, scenario.latitude_rad, scenario.height_m);
  // At rest the accelerometers feel the support force, +g along Up.
  state_.specific_force_body_m_s2 = enu_to_body * Eigen::Vector3d(0.0, 0.0, gravity);
  state_.angular_rate_body_rad_s = enu_to_body * earth_rate_enu_rad_s(scenario.earth_model, scenario.latitude_rad);
  state_.latitude_rad = scenario.latitude_rad;
  state_.longitude_rad = scenario.longitude_rad;
  state_.height_m = scenario.height_m;
  state_.temperature_c = scenario.temperature_c;
}

TruthIncrement StaticMotionSource::increment(double, double interval_s) {
  TruthIncrement result;
  result.delta_angle_rad = state_.angular_rate_body_rad_s * interval_s;
  result.delta_velocity_m_s = state_.specific_force_body_m_s2 * interval_s;
  result.mean_temperature_c = state_.temperature_c;
  return result;
}

TruthState StaticMotionSource::truth_at(double time_s) const {
  TruthState truth = state_;
  truth.time_s = time_s;
  return truth;
}

}  // namespace emulator
}  // namespace imu_lab
