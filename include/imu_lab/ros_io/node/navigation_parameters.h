// The strapdown navigator's ROS parameters (private namespace) -> pipeline::NavigationSettings.
//   align (true); alignment_duration_s (300); heading_source (gyrocompass | given);
//   initial_roll_deg, initial_pitch_deg (used with align: false), initial_yaw_deg (with
//   heading_source given or align: false; REP-103: from east towards north) (0);
//   initial_velocity_enu_m_s (required with align: false; with align: true only [0, 0, 0]: an
//   alignment starts at rest);
//   latitude_deg, longitude_deg, height_m (0): initial position, origin of the world frame;
//   earth_model (wgs84 | sphere); vertical_channel (held | free); reference_height_m (height_m);
//   coning_correction, sculling_correction (true); gap_factor (3);
//   expected_gyro_bias_rad_s, expected_accel_bias_m_s2, gyro_noise_density_rad_s_per_sqrt_hz,
//   accel_noise_density_m_s2_per_sqrt_hz: only for the predicted alignment errors; when none is
//   given there is no prediction (NaN), otherwise the missing ones are 0.
#pragma once

#include <ros/node_handle.h>

#include "imu_lab/pipeline/navigation_settings.h"

namespace imu_lab {
namespace ros_io {

// Throws ConfigError naming the parameter that is wrong.
pipeline::NavigationSettings load_navigation_settings(const ros::NodeHandle& private_node);

}  // namespace ros_io
}  // namespace imu_lab
