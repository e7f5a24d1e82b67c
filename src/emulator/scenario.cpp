#include "imu_lab/emulator/scenario.h"

#include <cmath>

#include "imu_lab/emulator/static_motion.h"
#include "yaml_fields.h"

namespace imu_lab {
namespace emulator {

namespace {
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
}

ScenarioConfig scenario_from_yaml(const YAML::Node& root, const std::string& source_name) {
  const YamlFields f(root, "", source_name);
  f.allow_only({"type", "description", "latitude_deg", "longitude_deg", "height_m", "roll_deg",
                "pitch_deg", "yaw_deg", "temperature_c", "earth_model", "duration_s"});
  ScenarioConfig scenario;
  scenario.source = source_name;
  scenario.type = f.text("type");
  if (scenario.type != "static") f.fail("type", "only 'static' scenarios exist so far");
  scenario.latitude_rad = f.number("latitude_deg") * kDegToRad;
  if (std::abs(scenario.latitude_rad) > 90.0 * kDegToRad) f.fail("latitude_deg", "must lie in [-90, 90]");
  scenario.longitude_rad = f.number("longitude_deg") * kDegToRad;
  scenario.height_m = f.number("height_m");
  scenario.roll_rad = f.number("roll_deg") * kDegToRad;
  scenario.pitch_rad = f.number("pitch_deg") * kDegToRad;
  scenario.yaw_rad = f.number("yaw_deg") * kDegToRad;
  scenario.temperature_c = f.number("temperature_c");
  const std::string earth = f.text("earth_model");
  if (earth == "wgs84_rotating") {
    scenario.earth_model = EarthModel::kWgs84Rotating;
  } else if (earth == "sphere_non_rotating") {
    scenario.earth_model = EarthModel::kSphereNonRotating;
  } else {
    f.fail("earth_model", "expected 'wgs84_rotating' or 'sphere_non_rotating', got '" + earth + "'");
  }
  scenario.duration_s = f.positive("duration_s");
  return scenario;
}

ScenarioConfig load_scenario(const std::string& path) {
  return scenario_from_yaml(load_yaml_file(path), path);
}

std::unique_ptr<MotionSource> make_motion_source(const ScenarioConfig& scenario) {
  return std::make_unique<StaticMotionSource>(scenario);
}

}  // namespace emulator
}  // namespace imu_lab
