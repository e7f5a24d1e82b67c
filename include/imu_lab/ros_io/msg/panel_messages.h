// The rviz panels' inputs from their messages: imu_lab/AllanDeviation and imu_lab/NoiseParameters
// into the ROS-free panel model (panel/allan_plot.h), parallel arrays shorter than their
// message's tau_s or term list reading as NaN there; nav_msgs/Odometry, imu_lab/Alignment and
// diagnostic_msgs/DiagnosticStatus into the attitude panel's (panel/attitude_view.h).
#pragma once

#include <imu_lab/AllanDeviation.h>
#include <diagnostic_msgs/DiagnosticStatus.h>
#include <imu_lab/Alignment.h>
#include <imu_lab/NoiseParameters.h>
#include <nav_msgs/Odometry.h>

#include "imu_lab/panel/allan_plot.h"
#include "imu_lab/panel/attitude_view.h"

namespace imu_lab {
namespace ros_io {

panel::StabilityCurves to_stability_curves(const imu_lab::AllanDeviation& message);
panel::NoiseAxisModel to_noise_axis_model(const imu_lab::NoiseAxis& message);
panel::NoiseReport to_noise_report(const imu_lab::NoiseParameters& message);

// The pose's orientation (body to ENU, REP-103) as roll, pitch and yaw.
panel::AttitudeSample to_attitude_sample(const nav_msgs::Odometry& message);
panel::AlignmentSummary to_alignment_summary(const imu_lab::Alignment& message);
panel::HealthStatus to_health_status(const diagnostic_msgs::DiagnosticStatus& message);

}  // namespace ros_io
}  // namespace imu_lab
