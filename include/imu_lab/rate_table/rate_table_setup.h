// What a rate-table test needs to know besides the recording: the site (latitude and Earth model,
// for the Earth rate's projection on the table axis), the table axis in ENU, how the IMU is
// mounted on the table (so which gyro axis lies along the table axis, and with which sign), and
// the nominal rates of the plateaus in the order the table ran them.
// From a rate_table scenario, or from a small YAML file for a real table (doc/rate_table.md):
//   latitude_deg: 50.45
//   earth_model: wgs84_rotating        # optional (or sphere_non_rotating)
//   axis_enu: [0, 0, 1]                # table axis [east, north, up]; optional, default up
//   roll_deg: 0                        # mount at table angle 0, as in the scenarios; optional
//   pitch_deg: 0
//   yaw_deg: 90
//   rates_deg_s: [1, -1, 10, -10, 100, -100, 0]
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace rate_table {

struct RateTableSetup {
  std::string source;
  double latitude_rad = 0.0;
  EarthShape earth_model = EarthShape::kWgs84Rotating;
  Eigen::Vector3d axis_enu = Eigen::Vector3d::UnitZ();  // unit
  Eigen::Quaterniond mount_body_to_enu = Eigen::Quaterniond::Identity();
  // Plateau rates in running order, consecutive repeats merged (one plateau on the recording).
  std::vector<double> nominal_rates_rad_s;

  // The table axis in body axes (fixed: the body turns about it).
  Eigen::Vector3d axis_body() const;
  // The gyro axis along the table axis (index, and +1 or -1 for its direction). Throws
  // ConfigError (key "roll_deg/pitch_deg/yaw_deg") unless one lies within 0.1 deg of it: an axis
  // at an angle to it would also see the horizontal Earth rate turning with the table.
  int tested_axis() const;
  double tested_axis_sign() const;
  // The Earth rate's component along the table axis (constant while the table turns).
  double earth_rate_on_axis_rad_s() const;
};

RateTableSetup setup_from_scenario(const emulator::ScenarioConfig& scenario);  // ConfigError unless rate_table
RateTableSetup load_rate_table_setup(const std::string& path);                 // ConfigError naming the key

}  // namespace rate_table
}  // namespace imu_lab
