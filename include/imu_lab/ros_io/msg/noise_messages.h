// imu_lab/NoiseParameters from an Allan run's identification (allan_noise_report.h), as the
// allan_monitor node publishes it on allan/noise: SI values, the unit key beside each.
#pragma once

#include <imu_lab/NoiseParameters.h>
#include <std_msgs/Header.h>

#include "imu_lab/allan/streaming_snapshot.h"
#include "imu_lab/identify/fit_result.h"
#include "imu_lab/identify/units.h"
#include "imu_lab/pipeline/allan_noise_report.h"

namespace imu_lab {
namespace ros_io {

// The relative one-sigma each term's required record length is computed for: a term is resolved
// when its amplitude is known to 10 %.
constexpr double kResolvedRelativeSigma = 0.1;

// One axis's fit: every term in report order, with the record each term of the model needs to reach
// target_relative_sigma (identify::required_record_length_s).
imu_lab::NoiseAxis to_noise_axis(identify::SensorKind sensor, int axis, const identify::FitResult& fit,
                                 double target_relative_sigma);

imu_lab::NoiseParameters to_noise_parameters(const pipeline::AllanNoiseReport& report,
                                             const allan::StreamingSnapshot& snapshot, const std_msgs::Header& header);

}  // namespace ros_io
}  // namespace imu_lab
