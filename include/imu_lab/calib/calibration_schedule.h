// Where the calibration happens and, for a table (mode 1), in which orientations the IMU rests.
// A multi-position scenario file (config/scenarios/multiposition_*.yaml) serves as the schedule:
// its positions, in order, are the orientations of the static intervals found in the recording.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace calib {

struct CalibrationSite {
  double latitude_rad = 0.0;
  double height_m = 0.0;
  EarthShape earth_model = EarthShape::kWgs84Rotating;

  double gravity_m_s2() const;  // WGS-84 normal gravity (Somigliana) at the site
  Eigen::Vector3d earth_rate_enu_rad_s() const;
};

struct TableSchedule {
  CalibrationSite site;
  std::vector<Eigen::Quaterniond> attitudes_body_to_enu;  // one per rest, in time order
  std::string source;
};

// Throws ConfigError (key "type") unless the scenario is a multi_position one.
TableSchedule schedule_from_scenario(const emulator::ScenarioConfig& scenario);

}  // namespace calib
}  // namespace imu_lab
