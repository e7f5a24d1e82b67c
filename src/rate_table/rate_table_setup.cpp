#include "imu_lab/rate_table/rate_table_setup.h"

#include <cmath>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/yaml_fields.h"
#include "imu_lab/emulator/earth_model.h"
#include "imu_lab/emulator/static_motion.h"

namespace imu_lab {
namespace rate_table {
namespace {

constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;
// The tested axis must lie within 0.1 deg of the table axis.
const double kMinAxisCosine = std::cos(0.1 * kRadPerDeg);

void append_merged(std::vector<double>& rates, double rate_rad_s) {
  if (rates.empty() || rates.back() != rate_rad_s) rates.push_back(rate_rad_s);
}

}  // namespace

Eigen::Vector3d RateTableSetup::axis_body() const { return mount_body_to_enu.conjugate() * axis_enu; }

int RateTableSetup::tested_axis() const {
  const Eigen::Vector3d axis = axis_body();
  Eigen::Index index = 0;
  axis.cwiseAbs().maxCoeff(&index);
  if (std::abs(axis[index]) < kMinAxisCosine) {
    throw ConfigError(source, "roll_deg/pitch_deg/yaw_deg",
                      "no gyro axis lies along the table axis (its direction in body axes is [" +
                          std::to_string(axis.x()) + ", " + std::to_string(axis.y()) + ", " + std::to_string(axis.z()) +
                          "]); mount the IMU with one axis on the table axis");
  }
  return static_cast<int>(index);
}

double RateTableSetup::tested_axis_sign() const { return axis_body()[tested_axis()] > 0.0 ? 1.0 : -1.0; }

double RateTableSetup::earth_rate_on_axis_rad_s() const {
  return emulator::earth_rate_enu_rad_s(earth_model, latitude_rad).dot(axis_enu);
}

RateTableSetup setup_from_scenario(const emulator::ScenarioConfig& scenario) {
  if (!scenario.rate_table) {
    throw ConfigError(scenario.source, "type",
                      "is '" + scenario.type + "'; a rate-table test needs a rate_table scenario");
  }
  RateTableSetup setup;
  setup.source = scenario.source;
  setup.latitude_rad = scenario.latitude_rad;
  setup.earth_model = scenario.earth_model;
  setup.axis_enu = scenario.rate_table->axis_enu;
  setup.mount_body_to_enu = scenario.rate_table->mount_body_to_enu;
  for (const auto& step : scenario.rate_table->steps) append_merged(setup.nominal_rates_rad_s, step.rate_rad_s);
  setup.tested_axis();  // refuses a mount without an axis on the table axis
  return setup;
}

RateTableSetup load_rate_table_setup(const std::string& path) {
  const YamlFields f(load_yaml_file(path), "", path);
  f.allow_only({"latitude_deg", "earth_model", "axis_enu", "roll_deg", "pitch_deg", "yaw_deg", "rates_deg_s"});
  RateTableSetup setup;
  setup.source = path;
  setup.latitude_rad = f.number("latitude_deg") * kRadPerDeg;
  if (std::abs(setup.latitude_rad) > 90.0 * kRadPerDeg) f.fail("latitude_deg", "must lie in [-90, 90]");
  if (f.has("earth_model")) {
    const std::string earth = f.text("earth_model");
    if (earth == "wgs84_rotating") {
      setup.earth_model = EarthShape::kWgs84Rotating;
    } else if (earth == "sphere_non_rotating") {
      setup.earth_model = EarthShape::kSphereNonRotating;
    } else {
      f.fail("earth_model", "expected 'wgs84_rotating' or 'sphere_non_rotating', got '" + earth + "'");
    }
  }
  if (f.has("axis_enu")) {
    const Eigen::Vector3d axis = f.per_axis("axis_enu", false);
    if (!(axis.norm() > 0.0)) f.fail("axis_enu", "must be a non-zero vector [east, north, up]");
    setup.axis_enu = axis.normalized();
  }
  setup.mount_body_to_enu = emulator::attitude_from_roll_pitch_yaw(f.number_or("roll_deg", 0.0) * kRadPerDeg,
                                                                   f.number_or("pitch_deg", 0.0) * kRadPerDeg,
                                                                   f.number_or("yaw_deg", 0.0) * kRadPerDeg);
  const YAML::Node rates = f.raw("rates_deg_s");
  if (!rates.IsSequence() || rates.size() < 3) f.fail("rates_deg_s", "must list at least three plateau rates");
  for (std::size_t k = 0; k < rates.size(); ++k) {
    append_merged(setup.nominal_rates_rad_s,
                  f.number_at(rates[k], "rates_deg_s[" + std::to_string(k) + "]") * kRadPerDeg);
  }
  setup.tested_axis();
  return setup;
}

}  // namespace rate_table
}  // namespace imu_lab
