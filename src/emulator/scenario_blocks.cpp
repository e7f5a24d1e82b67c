#include "scenario_blocks.h"

#include <cmath>

#include "imu_lab/emulator/static_motion.h"

namespace imu_lab {
namespace emulator {

namespace {
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

Eigen::Quaterniond read_orientation(const YamlFields& f) {
  return attitude_from_roll_pitch_yaw(f.number("roll_deg") * kDegToRad, f.number("pitch_deg") * kDegToRad,
                                      f.number("yaw_deg") * kDegToRad);
}

int read_body_axis(const YamlFields& f, const std::string& key) {
  const std::string name = f.text(key);
  if (name == "x") return 0;
  if (name == "y") return 1;
  if (name == "z") return 2;
  f.fail(key, "expected x, y or z, got '" + name + "'");
}

double non_negative_quantity(const YamlFields& f, const std::string& key) {
  const double value = f.number(key);
  if (value < 0.0) f.fail(key, "must be non-negative");
  return value;
}
}  // namespace

MultiPositionConfig read_multi_position(const YamlFields& f) {
  f.allow_only({"move_rate_deg_s", "move_acceleration_deg_s2", "positions"});
  MultiPositionConfig config;
  config.move_rate_rad_s = f.positive("move_rate_deg_s") * kDegToRad;
  config.move_acceleration_rad_s2 = f.positive("move_acceleration_deg_s2") * kDegToRad;
  for (const YamlFields& position : f.mappings("positions")) {
    position.allow_only({"roll_deg", "pitch_deg", "yaw_deg", "dwell_s"});
    config.positions.push_back({read_orientation(position), position.positive("dwell_s")});
  }
  return config;
}

RateTableConfig read_rate_table(const YamlFields& f) {
  f.allow_only({"axis_enu", "roll_deg", "pitch_deg", "yaw_deg", "acceleration_deg_s2", "steps"});
  RateTableConfig config;
  const Eigen::Vector3d axis = f.per_axis("axis_enu", false);
  if (!(axis.norm() > 0.0)) f.fail("axis_enu", "must be a non-zero vector [east, north, up]");
  config.axis_enu = axis.normalized();
  config.mount_body_to_enu = read_orientation(f);
  config.acceleration_rad_s2 = f.positive("acceleration_deg_s2") * kDegToRad;
  for (const YamlFields& step : f.mappings("steps")) {
    step.allow_only({"rate_deg_s", "hold_s"});
    config.steps.push_back({step.number("rate_deg_s") * kDegToRad, step.positive("hold_s")});
  }
  return config;
}

ConingConfig read_coning(const YamlFields& f) {
  f.allow_only({"roll_deg", "pitch_deg", "yaw_deg", "half_angle_deg", "frequency_hz"});
  ConingConfig config;
  config.mount_body_to_enu = read_orientation(f);
  config.half_angle_rad = f.positive("half_angle_deg") * kDegToRad;
  if (config.half_angle_rad >= 90.0 * kDegToRad) f.fail("half_angle_deg", "must be below 90");
  config.frequency_hz = f.positive("frequency_hz");
  return config;
}

ScullingConfig read_sculling(const YamlFields& f) {
  f.allow_only({"roll_deg", "pitch_deg", "yaw_deg", "rotation_axis", "vibration_axis", "angular_amplitude_deg",
                "displacement_amplitude_m", "frequency_hz", "phase_deg"});
  ScullingConfig config;
  config.mount_body_to_enu = read_orientation(f);
  config.rotation_axis = read_body_axis(f, "rotation_axis");
  config.vibration_axis = read_body_axis(f, "vibration_axis");
  if (config.vibration_axis == config.rotation_axis) {
    f.fail("vibration_axis", "must differ from rotation_axis (sculling needs perpendicular axes)");
  }
  config.angular_amplitude_rad = non_negative_quantity(f, "angular_amplitude_deg") * kDegToRad;
  config.displacement_amplitude_m = non_negative_quantity(f, "displacement_amplitude_m");
  config.frequency_hz = f.positive("frequency_hz");
  config.phase_rad = f.number_or("phase_deg", 0.0) * kDegToRad;
  return config;
}

TrajectoryConfig read_trajectory(const YamlFields& f) {
  f.allow_only({"initial_speed_m_s", "initial_yaw_deg", "legs"});
  TrajectoryConfig config;
  config.initial_speed_m_s = non_negative_quantity(f, "initial_speed_m_s");
  config.initial_yaw_rad = f.number("initial_yaw_deg") * kDegToRad;
  double speed_m_s = config.initial_speed_m_s;
  for (const YamlFields& leg : f.mappings("legs")) {
    leg.allow_only({"duration_s", "acceleration_m_s2", "yaw_rate_deg_s"});
    TrajectoryConfig::Leg parsed{leg.positive("duration_s"), leg.number("acceleration_m_s2"),
                                 leg.number("yaw_rate_deg_s") * kDegToRad};
    speed_m_s += parsed.acceleration_m_s2 * parsed.duration_s;
    if (speed_m_s < 0.0) leg.fail("acceleration_m_s2", "the speed would become negative in this leg");
    config.legs.push_back(parsed);
  }
  return config;
}

ThermalConfig read_thermal(const YamlFields& f) {
  f.allow_only({"initial_chamber_temperature_c", "sensor_time_constant_s", "second_sensor_time_constant_s",
                "self_heating", "segments"});
  ThermalConfig config;
  config.initial_chamber_temperature_c = f.number("initial_chamber_temperature_c");
  config.sensor_time_constant_s = f.positive("sensor_time_constant_s");
  if (f.has("second_sensor_time_constant_s")) {
    config.second_sensor_time_constant_s = f.positive("second_sensor_time_constant_s");
  }
  if (f.has("self_heating")) {
    const YamlFields heating = f.child("self_heating");
    heating.allow_only({"p1_c", "p2_per_s", "p3_c", "p4_per_s", "p5_c"});
    config.p1_c = heating.number("p1_c");
    config.p2_per_s = heating.number("p2_per_s");
    config.p3_c = heating.number("p3_c");
    config.p4_per_s = heating.number("p4_per_s");
    config.p5_c = heating.number("p5_c");
    for (const char* key : {"p2_per_s", "p4_per_s"}) {
      if (heating.number(key) > 0.0) heating.fail(key, "must be <= 0 (a transient that settles)");
    }
  }
  double chamber_c = config.initial_chamber_temperature_c;
  for (const YamlFields& segment : f.mappings("segments")) {
    segment.allow_only({"soak_s", "ramp_to_c", "rate_c_per_min"});
    if (segment.has("soak_s") == segment.has("ramp_to_c")) {
      segment.fail("soak_s", "give either soak_s or ramp_to_c (with rate_c_per_min)");
    }
    if (segment.has("soak_s")) {
      if (segment.has("rate_c_per_min")) segment.fail("rate_c_per_min", "a soak has no rate");
      config.segments.push_back({segment.positive("soak_s"), 0.0});
      continue;
    }
    const double target_c = segment.number("ramp_to_c");
    const double rate_c_s = segment.positive("rate_c_per_min") / 60.0;
    if (target_c == chamber_c) segment.fail("ramp_to_c", "equals the previous set point (use soak_s)");
    config.segments.push_back(
        {std::abs(target_c - chamber_c) / rate_c_s, std::copysign(rate_c_s, target_c - chamber_c)});
    chamber_c = target_c;
  }
  return config;
}

}  // namespace emulator
}  // namespace imu_lab
