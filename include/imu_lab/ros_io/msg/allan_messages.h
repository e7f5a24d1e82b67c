// imu_lab/AllanDeviation messages from a streaming Allan snapshot: one message per statistic and
// triad (gyro: channels 0-2, accel: channels 3-5), as the allan_monitor node publishes them.
#pragma once

#include <imu_lab/AllanDeviation.h>
#include <std_msgs/Header.h>

#include "imu_lab/allan/streaming_snapshot.h"
#include "imu_lab/allan/streaming_options.h"

namespace imu_lab {
namespace ros_io {

enum class AllanTriad { kGyro, kAccel };

// Axes share tau_s, the union of their taus; an axis without a point at a tau (its run split by
// NaNs) has NaN there.
imu_lab::AllanDeviation to_allan_deviation(const allan::StreamingSnapshot& snapshot, allan::Statistic statistic,
                                           AllanTriad triad, double confidence, const std_msgs::Header& header);

}  // namespace ros_io
}  // namespace imu_lab
