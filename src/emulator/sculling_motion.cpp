#include "imu_lab/emulator/sculling_motion.h"

#include <algorithm>
#include <cmath>

#include "imu_lab/emulator/local_level_kinematics.h"
#include "imu_lab/emulator/scenario_motions.h"

namespace imu_lab {
namespace emulator {

namespace {
constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
}

ScullingMotion::ScullingMotion(const ScenarioConfig& scenario)
    : SmoothPeriodicMotion(scenario, scenario.sculling.value().frequency_hz),
      sculling_(*scenario.sculling),
      vibration_enu_(sculling_.mount_body_to_enu * Eigen::Vector3d::Unit(sculling_.vibration_axis)) {}

TruthState ScullingMotion::truth_at(double time_s) const {
  const double w = kTwoPi * sculling_.frequency_hz;
  const double angle = sculling_.angular_amplitude_rad * std::sin(w * time_s);
  const double angle_rate = sculling_.angular_amplitude_rad * w * std::cos(w * time_s);
  const double vibration_phase = w * time_s + sculling_.phase_rad;
  const double d = sculling_.displacement_amplitude_m;
  const Eigen::Vector3d displacement_enu = d * std::sin(vibration_phase) * vibration_enu_;
  const Eigen::Vector3d rotation_axis = Eigen::Vector3d::Unit(sculling_.rotation_axis);

  const RadiiOfCurvature radii = radii_of_curvature(scenario_.earth_model, scenario_.latitude_rad);
  LocalLevelMotion motion;
  motion.latitude_rad = scenario_.latitude_rad + displacement_enu.y() / (radii.meridian_m + scenario_.height_m);
  motion.longitude_rad =
      scenario_.longitude_rad +
      displacement_enu.x() / ((radii.prime_vertical_m + scenario_.height_m) * std::cos(scenario_.latitude_rad));
  motion.height_m = scenario_.height_m + displacement_enu.z();
  motion.velocity_enu_m_s = d * w * std::cos(vibration_phase) * vibration_enu_;
  motion.acceleration_enu_m_s2 = -w * w * displacement_enu;
  motion.attitude_body_to_enu =
      sculling_.mount_body_to_enu * Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation_axis));
  motion.rate_body_wrt_enu_rad_s = angle_rate * rotation_axis;
  return truth_from_local_level(motion, scenario_.earth_model, time_s, scenario_.temperature_c);
}

std::unique_ptr<MotionSource> make_sculling_motion(const ScenarioConfig& scenario) {
  return std::make_unique<ScullingMotion>(scenario);
}

}  // namespace emulator
}  // namespace imu_lab
