// The rviz panels' inputs from their messages: imu_lab/AllanDeviation and imu_lab/NoiseParameters
// into the ROS-free panel model (panel/allan_plot.h). Parallel arrays shorter than their
// message's tau_s or term list read as NaN there.
#pragma once

#include <imu_lab/AllanDeviation.h>
#include <imu_lab/NoiseParameters.h>

#include "imu_lab/panel/allan_plot.h"

namespace imu_lab {
namespace ros_io {

panel::StabilityCurves to_stability_curves(const imu_lab::AllanDeviation& message);
panel::NoiseAxisModel to_noise_axis_model(const imu_lab::NoiseAxis& message);
panel::NoiseReport to_noise_report(const imu_lab::NoiseParameters& message);

}  // namespace ros_io
}  // namespace imu_lab
