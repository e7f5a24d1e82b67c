#include "imu_lab/emulator/coning_motion.h"

#include <algorithm>
#include <cmath>

#include "imu_lab/emulator/local_level_kinematics.h"
#include "imu_lab/emulator/scenario_motions.h"

namespace imu_lab {
namespace emulator {

namespace {
constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
}

Eigen::Quaterniond coning_attitude_body_to_mount(double half_angle_rad, double frequency_hz, double time_s) {
  const double phase = kTwoPi * frequency_hz * time_s;
  const double s = std::sin(0.5 * half_angle_rad);
  return Eigen::Quaterniond(std::cos(0.5 * half_angle_rad), s * std::cos(phase), s * std::sin(phase), 0.0);
}

Eigen::Vector3d coning_rate_body_wrt_mount_rad_s(double half_angle_rad, double frequency_hz, double time_s) {
  const double w = kTwoPi * frequency_hz;
  const double phase = w * time_s;
  const double s = std::sin(0.5 * half_angle_rad);
  return {-w * std::sin(half_angle_rad) * std::sin(phase), w * std::sin(half_angle_rad) * std::cos(phase),
          -2.0 * w * s * s};
}

ConingMotion::ConingMotion(const ScenarioConfig& scenario)
    : SmoothPeriodicMotion(scenario, scenario.coning.value().frequency_hz), coning_(*scenario.coning) {}

TruthState ConingMotion::truth_at(double time_s) const {
  LocalLevelMotion motion;
  motion.latitude_rad = scenario_.latitude_rad;
  motion.longitude_rad = scenario_.longitude_rad;
  motion.height_m = scenario_.height_m;
  motion.attitude_body_to_enu =
      coning_.mount_body_to_enu * coning_attitude_body_to_mount(coning_.half_angle_rad, coning_.frequency_hz, time_s);
  motion.rate_body_wrt_enu_rad_s =
      coning_rate_body_wrt_mount_rad_s(coning_.half_angle_rad, coning_.frequency_hz, time_s);
  return truth_from_local_level(motion, scenario_.earth_model, time_s, scenario_.temperature_c);
}

std::unique_ptr<MotionSource> make_coning_motion(const ScenarioConfig& scenario) {
  return std::make_unique<ConingMotion>(scenario);
}

}  // namespace emulator
}  // namespace imu_lab
