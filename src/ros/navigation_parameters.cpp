#include "imu_lab/ros/navigation_parameters.h"

#include "imu_lab/ros/node_parameters.h"

namespace imu_lab {
namespace ros_io {
namespace {

double degrees_parameter_rad(const ros::NodeHandle& node, const std::string& name) {
  return parameter(node, name, 0.0) * kDegToRad;
}

}  // namespace

NavigationSettings load_navigation_settings(const ros::NodeHandle& private_node) {
  NavigationSettings settings;
  const ros::NodeHandle& p = private_node;
  settings.align = parameter(p, "align", true);
  settings.alignment.duration_s = parameter(p, "alignment_duration_s", 300.0);
  settings.alignment.heading_source =
      parse_heading_source(p.resolveName("heading_source"), parameter<std::string>(p, "heading_source", "gyrocompass"));
  settings.initial_roll_rad = degrees_parameter_rad(p, "initial_roll_deg");
  settings.initial_pitch_rad = degrees_parameter_rad(p, "initial_pitch_deg");
  settings.initial_yaw_rad = degrees_parameter_rad(p, "initial_yaw_deg");
  settings.alignment.given_yaw_rad = settings.initial_yaw_rad;
  settings.latitude_rad = degrees_parameter_rad(p, "latitude_deg");
  settings.longitude_rad = degrees_parameter_rad(p, "longitude_deg");
  settings.height_m = parameter(p, "height_m", 0.0);
  settings.navigator.earth =
      parse_earth_model(p.resolveName("earth_model"), parameter<std::string>(p, "earth_model", "wgs84"));
  settings.navigator.vertical.mode =
      parse_vertical_channel(p.resolveName("vertical_channel"), parameter<std::string>(p, "vertical_channel", "held"));
  settings.navigator.vertical.fixed_reference_height_m = parameter(p, "reference_height_m", settings.height_m);
  settings.navigator.corrections.coning_correction = parameter(p, "coning_correction", true);
  settings.navigator.corrections.sculling_correction = parameter(p, "sculling_correction", true);
  settings.gap_factor = parameter(p, "gap_factor", settings.gap_factor);
  settings.expected_errors.emplace();
  settings.expected_errors->gyro_bias_rad_s = parameter(p, "expected_gyro_bias_rad_s", 0.0);
  settings.expected_errors->accel_bias_m_s2 = parameter(p, "expected_accel_bias_m_s2", 0.0);
  settings.expected_errors->gyro_noise_density_rad_s_per_sqrt_hz = parameter(p, "gyro_noise_density_rad_s_per_sqrt_hz", 0.0);
  settings.expected_errors->accel_noise_density_m_s2_per_sqrt_hz =
      parameter(p, "accel_noise_density_m_s2_per_sqrt_hz", 0.0);
  validate(settings, p.getNamespace());
  return settings;
}

}  // namespace ros_io
}  // namespace imu_lab
