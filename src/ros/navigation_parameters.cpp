#include "imu_lab/ros/navigation_parameters.h"

namespace imu_lab {
namespace ros_io {
namespace {

double degrees_parameter_rad(const ros::NodeHandle& node, const std::string& name) {
  return node.param(name, 0.0) * kDegToRad;
}

}  // namespace

NavigationSettings load_navigation_settings(const ros::NodeHandle& private_node) {
  NavigationSettings settings;
  const ros::NodeHandle& p = private_node;
  settings.align = p.param("align", true);
  settings.alignment.duration_s = p.param("alignment_duration_s", 300.0);
  settings.alignment.heading_source =
      parse_heading_source(p.resolveName("heading_source"), p.param<std::string>("heading_source", "gyrocompass"));
  settings.initial_roll_rad = degrees_parameter_rad(p, "initial_roll_deg");
  settings.initial_pitch_rad = degrees_parameter_rad(p, "initial_pitch_deg");
  settings.initial_yaw_rad = degrees_parameter_rad(p, "initial_yaw_deg");
  settings.alignment.given_yaw_rad = settings.initial_yaw_rad;
  settings.latitude_rad = degrees_parameter_rad(p, "latitude_deg");
  settings.longitude_rad = degrees_parameter_rad(p, "longitude_deg");
  settings.height_m = p.param("height_m", 0.0);
  settings.navigator.earth =
      parse_earth_model(p.resolveName("earth_model"), p.param<std::string>("earth_model", "wgs84"));
  settings.navigator.vertical.mode =
      parse_vertical_channel(p.resolveName("vertical_channel"), p.param<std::string>("vertical_channel", "held"));
  settings.navigator.vertical.fixed_reference_height_m = p.param("reference_height_m", settings.height_m);
  settings.navigator.corrections.coning_correction = p.param("coning_correction", true);
  settings.navigator.corrections.sculling_correction = p.param("sculling_correction", true);
  settings.gap_factor = p.param("gap_factor", settings.gap_factor);
  settings.expected_errors.gyro_bias_rad_s = p.param("expected_gyro_bias_rad_s", 0.0);
  settings.expected_errors.accel_bias_m_s2 = p.param("expected_accel_bias_m_s2", 0.0);
  settings.expected_errors.gyro_noise_density_rad_s_per_sqrt_hz = p.param("gyro_noise_density_rad_s_per_sqrt_hz", 0.0);
  settings.expected_errors.accel_noise_density_m_s2_per_sqrt_hz =
      p.param("accel_noise_density_m_s2_per_sqrt_hz", 0.0);
  validate(settings, p.getNamespace());
  return settings;
}

}  // namespace ros_io
}  // namespace imu_lab
