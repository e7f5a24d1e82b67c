#include "imu_lab/ros_io/node/navigation_parameters.h"

#include <algorithm>
#include <iterator>

#include "imu_lab/ros_io/node/node_parameters.h"

namespace imu_lab {
namespace ros_io {
namespace {

double degrees_parameter_rad(const ros::NodeHandle& node, const std::string& name) {
  return parameter(node, name, 0.0) * pipeline::kDegToRad;
}

// Without alignment the node starts from the given state and has no truth to take the velocity
// from (the tool has, in a bag with /imu/truth): a silent [0, 0, 0] would be a moving start's
// whole error, so it must be given then. With an alignment the start is at rest.
Eigen::Vector3d initial_velocity_parameter(const ros::NodeHandle& node, bool align) {
  const std::string name = "initial_velocity_enu_m_s";
  if (!align && !has_parameter(node, name)) {
    throw parameter_error(node, name,
                          "is required with align: false (the start is the given state; [0, 0, 0] for a start at "
                          "rest)");
  }
  const std::vector<double> value = parameter(node, name, std::vector<double>{0.0, 0.0, 0.0});
  if (value.size() != 3) {
    throw parameter_error(node, name,
                          "expected [east, north, up] in m/s, got " + std::to_string(value.size()) + " numbers");
  }
  return Eigen::Vector3d(value[0], value[1], value[2]);  // finiteness: pipeline::validate()
}

// Only when at least one is given: without them there is nothing to predict from.
std::optional<pipeline::ExpectedSensorErrors> expected_errors_parameters(const ros::NodeHandle& node) {
  const char* const names[] = {"expected_gyro_bias_rad_s", "expected_accel_bias_m_s2",
                               "gyro_noise_density_rad_s_per_sqrt_hz", "accel_noise_density_m_s2_per_sqrt_hz"};
  if (std::none_of(std::begin(names), std::end(names), [&](const char* name) { return has_parameter(node, name); })) {
    return std::nullopt;
  }
  pipeline::ExpectedSensorErrors expected;
  expected.gyro_bias_rad_s = parameter(node, names[0], 0.0);
  expected.accel_bias_m_s2 = parameter(node, names[1], 0.0);
  expected.gyro_noise_density_rad_s_per_sqrt_hz = parameter(node, names[2], 0.0);
  expected.accel_noise_density_m_s2_per_sqrt_hz = parameter(node, names[3], 0.0);
  return expected;
}

}  // namespace

pipeline::NavigationSettings load_navigation_settings(const ros::NodeHandle& private_node) {
  pipeline::NavigationSettings settings;
  const ros::NodeHandle& p = private_node;
  settings.align = parameter(p, "align", true);
  settings.alignment.duration_s = parameter(p, "alignment_duration_s", 300.0);
  settings.alignment.heading_source = pipeline::parse_heading_source(
      p.resolveName("heading_source"), parameter<std::string>(p, "heading_source", "gyrocompass"));
  settings.initial_roll_rad = degrees_parameter_rad(p, "initial_roll_deg");
  settings.initial_pitch_rad = degrees_parameter_rad(p, "initial_pitch_deg");
  settings.initial_yaw_rad = degrees_parameter_rad(p, "initial_yaw_deg");
  settings.alignment.given_yaw_rad = settings.initial_yaw_rad;
  settings.initial_velocity_enu_m_s = initial_velocity_parameter(p, settings.align);
  settings.latitude_rad = degrees_parameter_rad(p, "latitude_deg");
  settings.longitude_rad = degrees_parameter_rad(p, "longitude_deg");
  settings.height_m = parameter(p, "height_m", 0.0);
  settings.navigator.earth =
      pipeline::parse_earth_model(p.resolveName("earth_model"), parameter<std::string>(p, "earth_model", "wgs84"));
  settings.navigator.vertical.mode = pipeline::parse_vertical_channel(
      p.resolveName("vertical_channel"), parameter<std::string>(p, "vertical_channel", "held"));
  settings.navigator.vertical.fixed_reference_height_m = parameter(p, "reference_height_m", settings.height_m);
  settings.navigator.corrections.coning_correction = parameter(p, "coning_correction", true);
  settings.navigator.corrections.sculling_correction = parameter(p, "sculling_correction", true);
  settings.gap_factor = parameter(p, "gap_factor", settings.gap_factor);
  settings.expected_errors = expected_errors_parameters(p);
  pipeline::validate(settings, p.getNamespace());
  return settings;
}

}  // namespace ros_io
}  // namespace imu_lab
