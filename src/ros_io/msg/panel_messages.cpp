#include "imu_lab/ros_io/msg/panel_messages.h"

#include <limits>

#include "imu_lab/pipeline/navigation_settings.h"

namespace imu_lab {
namespace ros_io {
namespace {

template <typename T>
T entry_or(const std::vector<T>& values, std::size_t index, T fallback) {
  return index < values.size() ? values[index] : fallback;
}

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

}  // namespace

panel::StabilityCurves to_stability_curves(const imu_lab::AllanDeviation& message) {
  panel::StabilityCurves curves;
  curves.statistic = message.statistic;
  curves.sensor = message.sensor;
  curves.unit = message.unit;
  curves.tau0_s = message.tau0_s;
  curves.confidence = message.confidence;
  curves.samples = message.samples;
  curves.tau_s = message.tau_s;
  for (const imu_lab::AllanAxis& axis : message.axes) {
    panel::StabilityAxis out;
    out.name = axis.axis;
    for (std::size_t i = 0; i < message.tau_s.size(); ++i) {
      out.deviation.push_back(entry_or(axis.deviation, i, kMissing));
      out.lower.push_back(entry_or(axis.lower, i, kMissing));
      out.upper.push_back(entry_or(axis.upper, i, kMissing));
    }
    curves.axes.push_back(out);
  }
  return curves;
}

panel::NoiseAxisModel to_noise_axis_model(const imu_lab::NoiseAxis& message) {
  panel::NoiseAxisModel axis;
  axis.axis = message.axis;
  axis.output_quantization_density = message.output_quantization_density;
  for (std::size_t i = 0; i < message.term.size(); ++i) {
    panel::NoiseTerm term;
    term.name = message.term[i];
    term.symbol = entry_or(message.symbol, i, std::string());
    term.status = entry_or(message.status, i, std::string());
    term.value = entry_or(message.value, i, kMissing);
    term.shape = entry_or(message.shape, i, kMissing);
    term.width = entry_or(message.width, i, kMissing);
    term.required_record_length_s = entry_or(message.required_record_length_s, i, kMissing);
    axis.terms.push_back(term);
  }
  return axis;
}

panel::NoiseReport to_noise_report(const imu_lab::NoiseParameters& message) {
  panel::NoiseReport report;
  report.tau0_s = message.tau0_s;
  report.record_length_s = message.record_length_s;
  report.target_relative_sigma = message.target_relative_sigma;
  report.problems = message.problems;
  for (const imu_lab::NoiseTriad& triad : message.triads) {
    for (const imu_lab::NoiseAxis& axis : triad.axes) report.axes.push_back(to_noise_axis_model(axis));
  }
  return report;
}

panel::AttitudeSample to_attitude_sample(const nav_msgs::Odometry& message) {
  const auto& q = message.pose.pose.orientation;
  const Eigen::Vector3d roll_pitch_yaw =
      pipeline::roll_pitch_yaw_from_quaternion(Eigen::Quaterniond(q.w, q.x, q.y, q.z));
  return {roll_pitch_yaw.x(), roll_pitch_yaw.y(), roll_pitch_yaw.z()};
}

panel::AlignmentSummary to_alignment_summary(const imu_lab::Alignment& message) {
  panel::AlignmentSummary alignment;
  alignment.method = message.method;
  alignment.duration_s = message.duration_s;
  const auto& sigma = message.predicted_error_sigma_rad;
  alignment.error_sigma_enu_rad = {sigma.x, sigma.y, sigma.z};
  return alignment;
}

panel::HealthStatus to_health_status(const diagnostic_msgs::DiagnosticStatus& message) {
  return {message.name, static_cast<int>(message.level), message.message};
}

}  // namespace ros_io
}  // namespace imu_lab
