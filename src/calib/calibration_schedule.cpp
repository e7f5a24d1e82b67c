#include "imu_lab/calib/calibration_schedule.h"

#include "imu_lab/common/config_error.h"
#include "imu_lab/emulator/earth_model.h"

namespace imu_lab {
namespace calib {

double CalibrationSite::gravity_m_s2() const {
  return emulator::normal_gravity_m_s2(earth_model, latitude_rad, height_m);
}

Eigen::Vector3d CalibrationSite::earth_rate_enu_rad_s() const {
  return emulator::earth_rate_enu_rad_s(earth_model, latitude_rad);
}

TableSchedule schedule_from_scenario(const emulator::ScenarioConfig& scenario) {
  if (scenario.type != "multi_position" || !scenario.multi_position) {
    throw ConfigError(scenario.source, "type",
                      "a calibration schedule must be a multi_position scenario (this one is '" + scenario.type +
                          "'); omit the schedule to calibrate with unknown orientations");
  }
  TableSchedule schedule;
  schedule.site.latitude_rad = scenario.latitude_rad;
  schedule.site.height_m = scenario.height_m;
  schedule.site.earth_model = scenario.earth_model;
  schedule.source = scenario.source;
  for (const auto& position : scenario.multi_position->positions) {
    schedule.attitudes_body_to_enu.push_back(position.attitude_body_to_enu);
  }
  return schedule;
}

}  // namespace calib
}  // namespace imu_lab
