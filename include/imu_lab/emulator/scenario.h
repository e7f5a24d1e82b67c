// Scenario configuration (config/scenarios/*.yaml) and the motion source built from it.
// A scenario is independent of the sensor profile: any profile runs in any scenario.
// Scenario time runs from 0 at the start of the run (the emulator's start_time_s).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "imu_lab/emulator/motion_source.h"
#include "imu_lab/common/earth_constants.h"

namespace YAML {
class Node;
}

namespace imu_lab {
namespace emulator {

// Multi-position sequence on a table: dwell in each orientation, then rotate to the next about
// the single axis joining them, with a trapezoidal rate profile (accelerate, cruise, decelerate).
struct MultiPositionConfig {
  struct Position {
    Eigen::Quaterniond attitude_body_to_enu = Eigen::Quaterniond::Identity();
    double dwell_s = 0.0;
  };
  std::vector<Position> positions;
  double move_rate_rad_s = 0.0;           // cruise rate of a move
  double move_acceleration_rad_s2 = 0.0;  // and its acceleration / deceleration
};

// Rate table: the body, mounted in attitude `mount` at table angle 0, turns about a fixed ENU
// axis; it starts at rest and, for each step, changes rate at `acceleration` then holds.
// After the last step the table keeps its last rate.
struct RateTableConfig {
  struct Step {
    double rate_rad_s = 0.0;
    double hold_s = 0.0;
  };
  Eigen::Vector3d axis_enu = Eigen::Vector3d::UnitZ();  // unit
  Eigen::Quaterniond mount_body_to_enu = Eigen::Quaterniond::Identity();
  double acceleration_rad_s2 = 0.0;
  std::vector<Step> steps;
};

// Classical coning: attitude = mount * q(t), q(t) = [cos(a/2), sin(a/2) cos(W t),
// sin(a/2) sin(W t), 0]: the body z axis sweeps a cone of half-angle a about the mount's z.
struct ConingConfig {
  Eigen::Quaterniond mount_body_to_enu = Eigen::Quaterniond::Identity();
  double half_angle_rad = 0.0;
  double frequency_hz = 0.0;
};

// Sculling: angular oscillation angle(t) = A sin(W t) about a body axis, with a linear
// oscillation d(t) = D sin(W t + phase) along another mount axis (fixed in ENU).
struct ScullingConfig {
  Eigen::Quaterniond mount_body_to_enu = Eigen::Quaterniond::Identity();
  int rotation_axis = 0;   // 0 x, 1 y, 2 z (body)
  int vibration_axis = 1;  // of the mount (body at angle 0)
  double angular_amplitude_rad = 0.0;
  double displacement_amplitude_m = 0.0;
  double frequency_hz = 0.0;
  double phase_rad = 0.0;
};

// A level path over the Earth (constant height) from the scenario's start point: legs of
// constant along-track acceleration and constant yaw rate; the body's x axis points along the
// velocity, roll and pitch zero. After the last leg the vehicle keeps its speed and turn rate.
struct TrajectoryConfig {
  struct Leg {
    double duration_s = 0.0;
    double acceleration_m_s2 = 0.0;
    double yaw_rate_rad_s = 0.0;
  };
  double initial_speed_m_s = 0.0;
  double initial_yaw_rad = 0.0;  // 0 = East, counter-clockwise about Up (REP-103)
  std::vector<Leg> legs;
};

// Thermal profile: chamber set points (soaks and linear ramps), the sensor lagging the chamber
// by a first-order time constant plus the self-heating transient p1 e^{p2 t} + p3 e^{p4 t} + p5
// (Golovach 2017 eq. 3.3, t from power-on = scenario start), and an optional second thermosensor
// lagging the first. At t = 0 both sensors read chamber + self-heating(0) (in equilibrium).
struct ThermalConfig {
  struct Segment {
    double duration_s = 0.0;
    double rate_c_s = 0.0;  // 0 for a soak
  };
  double initial_chamber_temperature_c = 20.0;
  std::vector<Segment> segments;
  double sensor_time_constant_s = 0.0;
  std::optional<double> second_sensor_time_constant_s;
  double p1_c = 0.0, p2_per_s = 0.0, p3_c = 0.0, p4_per_s = 0.0, p5_c = 0.0;
};

struct ScenarioConfig {
  // static | multi_position | rate_table | coning | sculling | trajectory
  std::string type = "static";
  double latitude_rad = 0.0;
  double longitude_rad = 0.0;
  double height_m = 0.0;
  // Static body orientation w.r.t. local ENU: attitude = Rz(yaw) * Ry(pitch) * Rx(roll), body->ENU.
  // Yaw 0 = body x pointing East, counter-clockwise about Up (REP-103).
  double roll_rad = 0.0;
  double pitch_rad = 0.0;
  double yaw_rad = 0.0;
  double temperature_c = 25.0;  // constant, when there is no thermal block
  EarthShape earth_model = EarthShape::kWgs84Rotating;
  double duration_s = 0.0;
  std::string source;
  // The block matching `type` (none for static), and the optional thermal profile.
  std::optional<MultiPositionConfig> multi_position;
  std::optional<RateTableConfig> rate_table;
  std::optional<ConingConfig> coning;
  std::optional<ScullingConfig> sculling;
  std::optional<TrajectoryConfig> trajectory;
  std::optional<ThermalConfig> thermal;
};

// YAML keys (every angle in degrees, rates deg/s, accelerations deg/s^2; see
// config/scenarios/*.yaml for commented examples):
//   type, latitude_deg, longitude_deg, height_m, earth_model (wgs84_rotating |
//   sphere_non_rotating), duration_s, temperature_c (without thermal), description;
//   static: roll_deg, pitch_deg, yaw_deg;
//   multi_position: {move_rate_deg_s, move_acceleration_deg_s2,
//                    positions: [{roll_deg, pitch_deg, yaw_deg, dwell_s}, ...]};
//   rate_table: {axis_enu: [e, n, u], roll_deg, pitch_deg, yaw_deg, acceleration_deg_s2,
//                steps: [{rate_deg_s, hold_s}, ...]};
//   coning: {roll_deg, pitch_deg, yaw_deg, half_angle_deg, frequency_hz};
//   sculling: {roll_deg, pitch_deg, yaw_deg, rotation_axis (x|y|z), vibration_axis (x|y|z),
//              angular_amplitude_deg, displacement_amplitude_m, frequency_hz, phase_deg};
//   trajectory: {initial_speed_m_s, initial_yaw_deg,
//                legs: [{duration_s, acceleration_m_s2, yaw_rate_deg_s}, ...]};
//   thermal (optional, any type): {initial_chamber_temperature_c, sensor_time_constant_s,
//                second_sensor_time_constant_s (optional),
//                self_heating: {p1_c, p2_per_s, p3_c, p4_per_s, p5_c} (optional),
//                segments: [{soak_s} | {ramp_to_c, rate_c_per_min}, ...]}.
ScenarioConfig load_scenario(const std::string& path);
ScenarioConfig scenario_from_yaml(const YAML::Node& root, const std::string& source_name);

std::unique_ptr<MotionSource> make_motion_source(const ScenarioConfig& scenario);

}  // namespace emulator
}  // namespace imu_lab
