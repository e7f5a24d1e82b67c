#include "imu_lab/ros_io/msg/noise_messages.h"

#include <limits>

#include "imu_lab/identify/record_length.h"

namespace imu_lab {
namespace ros_io {

imu_lab::NoiseAxis to_noise_axis(identify::SensorKind sensor, int axis, const identify::FitResult& fit,
                                 double target_relative_sigma) {
  imu_lab::NoiseAxis message;
  message.axis = identify::axis_name(sensor, axis);
  for (const identify::TermEstimate* term : identify::terms_in_report_order(fit)) {
    const auto units = identify::amplitude_units(sensor, term->kind);
    message.term.push_back(term->name);
    message.symbol.push_back(identify::amplitude_symbol(term->kind));
    message.status.push_back(identify::term_status_name(term->status));
    message.unit.push_back(units.empty() ? "" : units.front().key);  // SI comes first
    message.value.push_back(term->amplitude.value);
    message.sigma.push_back(term->amplitude.sigma);
    message.upper_bound.push_back(term->amplitude.upper_bound);
    message.sigma_source.push_back(identify::sigma_source_name(term->sigma_source));
    message.borderline.push_back(term->borderline);
    const bool shaped = identify::has_shape(term->kind);
    const auto shape_units = identify::shape_units(term->kind);
    message.shape_symbol.push_back(shaped ? identify::shape_symbol(term->kind) : "");
    message.shape_unit.push_back(shaped && !shape_units.empty() ? shape_units.front().key : "");
    message.shape.push_back(shaped ? term->shape.value : identify::ParameterEstimate::kNotAvailable);
    message.width.push_back(term->width.value);
    message.required_record_length_s.push_back(
        term->status == identify::TermStatus::kAbsent
            ? std::numeric_limits<double>::quiet_NaN()
            : identify::required_record_length_s(fit, term->name, target_relative_sigma));
  }
  message.output_quantization_density = fit.model.output_quantization_density;
  message.warnings = fit.warnings;
  return message;
}

imu_lab::NoiseParameters to_noise_parameters(const pipeline::AllanNoiseReport& report,
                                             const allan::StreamingSnapshot& snapshot, const std_msgs::Header& header) {
  imu_lab::NoiseParameters message;
  message.header = header;
  message.tau0_s = snapshot.timing.tau0_s;
  message.record_length_s = pipeline::record_length_s(snapshot);
  message.target_relative_sigma = kResolvedRelativeSigma;
  message.problems = report.problems;
  for (const identify::TriadFit& triad : report.triads) {
    imu_lab::NoiseTriad triad_message;
    triad_message.sensor = identify::sensor_prefix(triad.sensor);
    triad_message.worst_axis = static_cast<std::uint8_t>(triad.worst_axis);
    triad_message.worst_axis_reason = triad.worst_axis_reason;
    for (int axis = 0; axis < 3; ++axis) {
      triad_message.axes.push_back(to_noise_axis(triad.sensor, axis, triad.axes[axis], kResolvedRelativeSigma));
    }
    message.triads.push_back(triad_message);
  }
  return message;
}

}  // namespace ros_io
}  // namespace imu_lab
