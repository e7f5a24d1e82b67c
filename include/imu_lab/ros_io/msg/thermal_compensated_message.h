// The sensor_msgs/Imu that thermal compensation publishes for one decided sample: the input
// message (header, orientation, covariances) with the compensated angular rate and specific force.
// Covariances stay: (1 + delta_scale)^2 changes them by parts per thousand at most.
// Shared by the thermal_compensator node and the offline `correct` tool.
#pragma once

#include <sensor_msgs/Imu.h>

#include "imu_lab/thermal/thermal_compensator.h"

namespace imu_lab {
namespace ros_io {

// `sample` must not be stale (a stale sample is not published at all).
sensor_msgs::Imu thermal_compensated_message(const sensor_msgs::Imu& input, const thermal::CompensatedSample& sample);

}  // namespace ros_io
}  // namespace imu_lab
