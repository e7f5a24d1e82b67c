// One navigation solution as every output shows it (odometry, tf, path, trajectory CSV), and its
// error against the emulator's truth. Frames: world = local ENU (REP-103) at the initial
// position, body = IMU sensor frame (REP-145); see local_enu.h and nav/nav_state.h.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

#include "imu_lab/io/imu_records.h"
#include "imu_lab/nav/local_enu.h"
#include "imu_lab/pipeline/navigation_session.h"

namespace imu_lab {
namespace pipeline {

struct NavigationSolution {
  std::int64_t stamp_ns = 0;  // header stamp of the sample that produced it
  double latitude_rad = 0.0;
  double longitude_rad = 0.0;
  double height_m = 0.0;
  Eigen::Vector3d position_enu_m = Eigen::Vector3d::Zero();  // local ENU from the initial position
  Eigen::Vector3d velocity_enu_m_s = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_body_to_enu = Eigen::Quaterniond::Identity();
  Eigen::Vector3d roll_pitch_yaw_rad = Eigen::Vector3d::Zero();
  // Odometry twist (nav_msgs/Odometry: in the child, i.e. body, frame).
  Eigen::Vector3d velocity_body_m_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_rate_body_rad_s = Eigen::Vector3d::Zero();  // relative to the world frame
};

// The session's current solution (call while session.navigating()).
NavigationSolution make_solution(const NavigationSession& session, const nav::LocalEnuFrame& world);

struct NavigationError {
  std::int64_t stamp_ns = 0;
  double time_since_alignment_s = 0.0;
  Eigen::Vector3d position_error_enu_m = Eigen::Vector3d::Zero();  // estimate minus truth
  double horizontal_position_error_m = 0.0;
  double height_error_m = 0.0;
  Eigen::Vector3d velocity_error_enu_m_s = Eigen::Vector3d::Zero();
  // Small rotation with q_estimate = exp(error) q_truth, ENU axes: east tilt, north tilt, heading.
  Eigen::Vector3d attitude_error_enu_rad = Eigen::Vector3d::Zero();
};

NavigationError navigation_error(const NavigationSolution& solution, const io::TruthRecord& truth,
                                 const nav::LocalEnuFrame& world, std::int64_t alignment_stamp_ns);

}  // namespace pipeline
}  // namespace imu_lab
