#include "imu_lab/emulator/scenario.h"

#include <cmath>

#include "imu_lab/emulator/scenario_motions.h"
#include "imu_lab/emulator/static_motion.h"
#include "imu_lab/emulator/thermal_motion.h"
#include "scenario_blocks.h"
#include "imu_lab/common/site_limits.h"
#include "imu_lab/common/yaml_fields.h"

namespace imu_lab {
namespace emulator {

namespace {
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
const char* const kMotionTypes[] = {"multi_position", "rate_table", "coning", "sculling", "trajectory"};

// The block named after the type must be there; the other types' blocks must not.
void read_type_block(const YamlFields& f, ScenarioConfig& scenario) {
  for (const char* type : kMotionTypes) {
    if (scenario.type != type && f.has(type)) {
      f.fail(type, "a '" + std::string(type) + "' block in a scenario of type '" + scenario.type + "'");
    }
  }
  if (scenario.type == "static") {
    scenario.roll_rad = f.number("roll_deg") * kDegToRad;
    scenario.pitch_rad = f.number("pitch_deg") * kDegToRad;
    scenario.yaw_rad = f.number("yaw_deg") * kDegToRad;
    return;
  }
  for (const char* key : {"roll_deg", "pitch_deg", "yaw_deg"}) {
    if (f.has(key))
      f.fail(key, "only static scenarios take it here; put the orientation in the '" + scenario.type + "' block");
  }
  const YamlFields block = f.child(scenario.type);
  if (scenario.type == "multi_position") scenario.multi_position = read_multi_position(block);
  if (scenario.type == "rate_table") scenario.rate_table = read_rate_table(block);
  if (scenario.type == "coning") scenario.coning = read_coning(block);
  if (scenario.type == "sculling") scenario.sculling = read_sculling(block);
  if (scenario.type == "trajectory") scenario.trajectory = read_trajectory(block);
}
}  // namespace

ScenarioConfig scenario_from_yaml(const YAML::Node& root, const std::string& source_name) {
  const YamlFields f(root, "", source_name);
  f.allow_only({"type", "description", "latitude_deg", "longitude_deg", "height_m", "roll_deg", "pitch_deg", "yaw_deg",
                "temperature_c", "earth_model", "duration_s", "multi_position", "rate_table", "coning", "sculling",
                "trajectory", "thermal"});
  ScenarioConfig scenario;
  scenario.source = source_name;
  scenario.type = f.text("type");
  bool known = scenario.type == "static";
  for (const char* type : kMotionTypes) known = known || scenario.type == type;
  if (!known) {
    f.fail("type", "unknown scenario type '" + scenario.type +
                       "' (expected static, multi_position, rate_table, coning, sculling or trajectory)");
  }
  scenario.latitude_rad = f.number("latitude_deg") * kDegToRad;
  if (std::abs(scenario.latitude_rad) > 90.0 * kDegToRad) f.fail("latitude_deg", "must lie in [-90, 90]");
  scenario.longitude_rad = f.number("longitude_deg") * kDegToRad;
  const double longitude_deg = scenario.longitude_rad / kDegToRad;
  if (!(longitude_deg >= site_limits::kLowestLongitudeDeg && longitude_deg <= site_limits::kHighestLongitudeDeg)) {
    f.fail("longitude_deg", "must lie in [-180, 360]");
  }
  scenario.height_m = f.number("height_m");
  if (!(scenario.height_m >= site_limits::kLowestHeightM && scenario.height_m <= site_limits::kHighestHeightM)) {
    f.fail("height_m", "must lie in [-11000, 100000] m (the deepest trench to the edge of space)");
  }
  if (f.has("thermal")) {
    if (f.has("temperature_c")) f.fail("temperature_c", "the thermal block sets the temperature; remove this key");
    scenario.thermal = read_thermal(f.child("thermal"));
    scenario.temperature_c = scenario.thermal->initial_chamber_temperature_c;
  } else {
    scenario.temperature_c = f.number("temperature_c");
  }
  const std::string earth = f.text("earth_model");
  if (earth == "wgs84_rotating") {
    scenario.earth_model = EarthShape::kWgs84Rotating;
  } else if (earth == "sphere_non_rotating") {
    scenario.earth_model = EarthShape::kSphereNonRotating;
  } else {
    f.fail("earth_model", "expected 'wgs84_rotating' or 'sphere_non_rotating', got '" + earth + "'");
  }
  scenario.duration_s = f.positive("duration_s");
  read_type_block(f, scenario);
  return scenario;
}

ScenarioConfig load_scenario(const std::string& path) { return scenario_from_yaml(load_yaml_file(path), path); }

std::unique_ptr<MotionSource> make_motion_source(const ScenarioConfig& scenario) {
  // The type's block must be filled (load_scenario does; hand-built configs must too).
  std::unique_ptr<MotionSource> motion;
  if (scenario.type == "multi_position") {
    motion = make_multi_position_motion(scenario);
  } else if (scenario.type == "rate_table") {
    motion = make_rate_table_motion(scenario);
  } else if (scenario.type == "coning") {
    motion = make_coning_motion(scenario);
  } else if (scenario.type == "sculling") {
    motion = make_sculling_motion(scenario);
  } else if (scenario.type == "trajectory") {
    motion = make_trajectory_motion(scenario);
  } else {
    motion = std::make_unique<StaticMotionSource>(scenario);
  }
  if (scenario.thermal) motion = std::make_unique<ThermalMotion>(std::move(motion), *scenario.thermal);
  return motion;
}

}  // namespace emulator
}  // namespace imu_lab
