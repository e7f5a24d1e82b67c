// imu_lab/NoiseParameters from an Allan run's identification (allan_noise_report.h), as the
// allan_monitor node publishes it on allan/noise: SI values, the unit key beside each.
#pragma once

#include <imu_lab/NoiseParameters.h>
#include <std_msgs/Header.h>

#include "imu_lab/allan/streaming_snapshot.h"
#include "imu_lab/ros/allan_noise_report.h"

namespace imu_lab {
namespace ros_io {

imu_lab::NoiseParameters to_noise_parameters(const AllanNoiseReport& report, const allan::StreamingSnapshot& snapshot,
                                             const std_msgs::Header& header);

}  // namespace ros_io
}  // namespace imu_lab
