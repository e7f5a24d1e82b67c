// What the attitude_error_budget tool does without ROS: the angular motion the prediction of
// nav/attitude_error_growth.h runs on, from an emulator scenario, constant body rates or a
// recording's measured rates (the
// body-to-ENU attitude on a uniform grid and the ENU frame's inertial rate, Earth rate plus
// transport rate, nav/earth_model.h); the gyros from a noise report; the CSV and the summary.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "imu_lab/emulator/scenario.h"
#include "imu_lab/io/imu_records.h"
#include "imu_lab/nav/attitude_error_growth.h"

namespace imu_lab {
namespace pipeline {

// The scenario's truth (attitude, latitude, height, velocity) every step_s from 0 to duration_s
// (the scenario's own duration when duration_s is 0), on the scenario's Earth. Throws ConfigError
// naming the option when neither gives a duration or step_s exceeds it.
std::vector<nav::AttitudeSample> scenario_attitude_motion(const emulator::ScenarioConfig& scenario, double duration_s,
                                                          double step_s);

// Constant body rates relative to ENU from the scenario's initial attitude (roll, pitch, yaw) at
// its site, the ENU frame turning at the Earth rate of its latitude.
std::vector<nav::AttitudeSample> constant_rate_scenario_motion(const emulator::ScenarioConfig& site,
                                                               const Eigen::Vector3d& body_rate_rad_s,
                                                               double duration_s, double step_s);

// The motion a recording's gyros measured, from the site's initial attitude (roll, pitch, yaw) at
// its latitude: each sample's rate held over the interval before its stamp (it is that interval's
// average), the Earth rate (projected with the attitude reached) taken out to leave the body's
// rate relative to ENU, integrated onto a grid of step_s from the first stamp, up to duration_s
// (0: as far as the records reach). The site does not move (no transport rate). The gyros' own
// errors turn the attitude a little too (a MEMS bias of 0.3 deg/s: 18 deg in a minute), which
// changes how the errors map into ENU, not their size. Throws std::invalid_argument naming the
// stamp for stamps that do not increase or a gap of more than 10 median intervals (the motion
// there is unknown), and for fewer than two records or a duration beyond them.
std::vector<nav::AttitudeSample> recorded_attitude_motion(const std::vector<io::ImuRecord>& records,
                                                          const emulator::ScenarioConfig& site, double duration_s,
                                                          double step_s);

// The gyro triad of a noise report (identify/noise_report.h), each axis with the same turn-on
// bias sigma (which no Allan curve shows).
std::array<nav::GyroAxisErrors, 3> gyros_from_noise_report(const std::string& path, double turn_on_bias_rad_s);

// One row per point: time_s, then strapdown_{east,north,up}_rad, platform_{east,north,up}_rad
// (1-sigma), then the root-sum-square over the axes of each (strapdown_total_rad,
// platform_total_rad).
std::string attitude_error_csv(const std::vector<nav::AttitudeErrorPoint>& points);
// A few rows (about 1, 10, 100, ... s and the end) in degrees and the ratio strapdown / platform.
std::string attitude_error_summary(const std::vector<nav::AttitudeErrorPoint>& points);

// Largest angle the body turns through, relative to ENU, between neighbouring samples [rad].
double largest_step_turn_rad(const std::vector<nav::AttitudeSample>& motion);

}  // namespace pipeline
}  // namespace imu_lab
