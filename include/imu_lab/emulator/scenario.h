// Scenario configuration (config/scenarios/*.yaml) and the motion source built from it.
#pragma once

#include <memory>
#include <string>

#include "imu_lab/emulator/motion_source.h"

namespace YAML {
class Node;
}

namespace imu_lab {
namespace emulator {

enum class EarthModel {
  kWgs84Rotating,      // WGS-84 ellipsoid, Somigliana normal gravity with height term, Earth rate
  kSphereNonRotating,  // sphere R = 6371 km, g = 9.81 m/s^2, no Earth rate
};

struct ScenarioConfig {
  std::string type = "static";
  double latitude_rad = 0.0;
  double longitude_rad = 0.0;
  double height_m = 0.0;
  // Body orientation w.r.t. local ENU: attitude = Rz(yaw) * Ry(pitch) * Rx(roll), body->ENU.
  // Yaw 0 = body x pointing East, counter-clockwise about Up (REP-103).
  double roll_rad = 0.0;
  double pitch_rad = 0.0;
  double yaw_rad = 0.0;
  double temperature_c = 25.0;
  EarthModel earth_model = EarthModel::kWgs84Rotating;
  double duration_s = 0.0;
  std::string source;
};

// YAML keys: type (static), latitude_deg, longitude_deg, height_m, roll_deg, pitch_deg, yaw_deg,
// temperature_c, earth_model (wgs84_rotating | sphere_non_rotating), duration_s.
ScenarioConfig load_scenario(const std::string& path);
ScenarioConfig scenario_from_yaml(const YAML::Node& root, const std::string& source_name);

std::unique_ptr<MotionSource> make_motion_source(const ScenarioConfig& scenario);

}  // namespace emulator
}  // namespace imu_lab
