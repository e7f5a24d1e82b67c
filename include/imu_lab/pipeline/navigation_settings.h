// What a strapdown run needs besides the IMU data: how to align, where it starts, and the
// navigator's models. The strapdown_navigator node fills it from ROS parameters
// (navigation_parameters.h), the navigate tool from its command line; both then run the same
// NavigationSession (navigation_session.h), so they give the same solution on the same data.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "imu_lab/nav/navigator.h"
#include "imu_lab/nav/static_alignment.h"

namespace imu_lab {
namespace pipeline {

constexpr double kDegToRad = M_PI / 180.0;

// A priori sensor errors, used only to predict the alignment errors reported with the result.
// Zero is a value (an error-free sensor); not giving them at all (std::nullopt in the settings)
// means no prediction.
struct ExpectedSensorErrors {
  double gyro_bias_rad_s = 0.0;                       // per axis, 1 sigma
  double accel_bias_m_s2 = 0.0;                       // per axis, 1 sigma
  double gyro_noise_density_rad_s_per_sqrt_hz = 0.0;  // angle random walk (rad/sqrt(s))
  double accel_noise_density_m_s2_per_sqrt_hz = 0.0;  // velocity random walk (m/s/sqrt(s))
};

// The expected errors from a noise report as `allan` writes it (noise.yaml, doc/formats.md), for
// the largest axis of each triad: the white noise density N of the white_rate term (with the
// output's quantisation density, which adds to it), and as the bias the bias instability B (0
// where the report has none). B is the bias's wander within the run; the turn-on bias, which no
// Allan curve shows, is not in it, so the bias is a lower bound (give it explicitly where known).
// Throws InputError naming the file (identify::load_reported_axis_models) when it cannot be read
// or lacks a triad.
ExpectedSensorErrors expected_errors_from_noise_report(const std::string& path);

struct NavigationSettings {
  // Static alignment first (levelling, heading from gyrocompassing or given), starting at rest;
  // or (align = false) start from a given state at the first sample's stamp: attitude (initial
  // roll, pitch and yaw, REP-103 ENU, yaw from east; or initial_attitude when set, e.g. the
  // truth's, which keeps attitudes that Euler angles cannot), velocity and position.
  bool align = true;
  nav::StaticAlignmentConfig alignment;
  double initial_roll_rad = 0.0;
  double initial_pitch_rad = 0.0;
  double initial_yaw_rad = 0.0;
  std::optional<Eigen::Quaterniond> initial_attitude_body_to_enu;  // align = false only
  // Velocity relative to the Earth at the start (align = false only; an alignment starts at rest).
  Eigen::Vector3d initial_velocity_enu_m_s = Eigen::Vector3d::Zero();
  // Initial position (geodetic); also the origin of the published local ENU position.
  double latitude_rad = 0.0;
  double longitude_rad = 0.0;
  double height_m = 0.0;
  nav::NavigatorConfig navigator;
  // A stamp interval longer than this many times the typical one is a gap: the sample after it is
  // not integrated (its rate says nothing about the missing time).
  double gap_factor = 3.0;
  std::optional<ExpectedSensorErrors> expected_errors;  // none: no predicted alignment error
};

// Parsers shared by the node's parameters and the tool's options; each throws ConfigError naming
// `key` and the accepted values.
nav::HeadingSource parse_heading_source(const std::string& key, const std::string& value);
nav::EarthModelConfig parse_earth_model(const std::string& key, const std::string& value);
nav::VerticalChannelMode parse_vertical_channel(const std::string& key, const std::string& value);

// Checks ranges (latitude inside (-90, 90) deg, positive durations, finite angles and velocity, no
// initial velocity with an alignment); throws ConfigError naming the offending key (`source` says
// where the settings came from).
void validate(const NavigationSettings& settings, const std::string& source);

// Roll, pitch, yaw of a body->ENU attitude with q = Rz(yaw) Ry(pitch) Rx(roll), the inverse of
// emulator::attitude_from_roll_pitch_yaw (pitch in [-pi/2, pi/2], yaw from east towards north).
Eigen::Vector3d roll_pitch_yaw_from_quaternion(const Eigen::Quaterniond& q_body_to_enu);

}  // namespace pipeline
}  // namespace imu_lab
