// The navigate tool's files: the trajectory CSV (one row per kept solution) and the error CSV
// against the truth, both written atomically; and the trajectory reader the rostest checker uses
// to compare the live node with the tool. Stamps are written exactly (seconds.nanoseconds from
// the integer stamp), so rows match messages by stamp without rounding.
//
// trajectory: stamp_s, latitude_rad, longitude_rad, height_m, east_m, north_m, up_m (local ENU
//   from the initial position), velocity_east_m_s, velocity_north_m_s, velocity_up_m_s,
//   roll_rad, pitch_rad, yaw_rad (REP-103, yaw from east towards north), qw, qx, qy, qz (body->ENU)
// errors: stamp_s, time_since_alignment_s, east_error_m, north_error_m, up_error_m,
//   horizontal_position_error_m, height_error_m, velocity_error_east_m_s, velocity_error_north_m_s,
//   velocity_error_up_m_s, attitude_error_east_rad, attitude_error_north_rad, attitude_error_up_rad
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "imu_lab/pipeline/navigation_solution.h"

namespace imu_lab {
namespace pipeline {

void write_trajectory_csv(const std::string& path, const std::vector<NavigationSolution>& solutions);
void write_error_csv(const std::string& path, const std::vector<NavigationError>& errors);

// Reads what write_trajectory_csv wrote (the velocity and rate in body axes are not stored and
// stay zero). Throws InputError naming the file and line on anything malformed.
std::vector<NavigationSolution> read_trajectory_csv(const std::string& path);

}  // namespace pipeline
}  // namespace imu_lab
