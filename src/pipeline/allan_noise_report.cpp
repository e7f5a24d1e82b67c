#include "imu_lab/pipeline/allan_noise_report.h"

#include <yaml-cpp/yaml.h>

#include <exception>

#include "imu_lab/common/cancellation.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/identify/bootstrap.h"
#include "imu_lab/identify/kalibr_yaml.h"
#include "imu_lab/identify/noise_report.h"
#include "imu_lab/identify/partial_curves.h"
#include "imu_lab/identify/units.h"
#include "imu_lab/pipeline/allan_samples.h"

namespace imu_lab {
namespace pipeline {
namespace {

using identify::SensorKind;

constexpr std::array<SensorKind, 2> kSensors = {SensorKind::kGyroscope, SensorKind::kAccelerometer};

std::size_t first_channel(SensorKind sensor) { return sensor == SensorKind::kGyroscope ? 0 : 3; }

std::array<std::vector<allan::StabilityPoint>, 3> oadev_curves(const allan::StreamingSnapshot& snapshot,
                                                               SensorKind sensor) {
  std::array<std::vector<allan::StabilityPoint>, 3> curves;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    curves[axis] = snapshot.curve(allan::Statistic::kOverlappingAllan, first_channel(sensor) + axis);
  }
  return curves;
}

// The output's LSB, where the run found one, is part of each axis's front end.
std::array<identify::FitOptions, 3> axis_options(SensorKind sensor, const AllanRunDescription& run,
                                                 const AllanIdentifyOptions& options) {
  std::array<identify::FitOptions, 3> per_axis;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    per_axis[axis] = options.fit;
    const std::size_t channel = first_channel(sensor) + axis;
    if (per_axis[axis].output_quantization_step == 0.0 && channel < run.output_steps.size() &&
        run.output_steps[channel].quantised) {
      per_axis[axis].output_quantization_step = run.output_steps[channel].step;
    }
  }
  return per_axis;
}

identify::TriadFit fit_sensor(SensorKind sensor, const AllanRunDescription& run,
                              const allan::StreamingSnapshot& snapshot, const AllanIdentifyOptions& options) {
  identify::TriadFit triad = identify::fit_triad(sensor, oadev_curves(snapshot, sensor), snapshot.timing.tau0_s,
                                                 record_length_s(snapshot), axis_options(sensor, run, options));
  if (options.bootstrap_replicas <= 0) return triad;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    identify::BootstrapOptions bootstrap;
    bootstrap.replicas = options.bootstrap_replicas;
    // One stream per channel: the axes' simulated records must not share their noise.
    bootstrap.seed = options.bootstrap_seed + first_channel(sensor) + axis;
    identify::apply_bootstrap(identify::bootstrap_uncertainty(triad.axes[axis], bootstrap), &triad.axes[axis]);
  }
  return triad;
}

double seconds_from(std::int64_t stamp_ns, std::int64_t first_stamp_ns) {
  return seconds_between(first_stamp_ns, stamp_ns);
}

identify::ReportMetadata report_metadata(const AllanRunDescription& run, const allan::StreamingSnapshot& snapshot) {
  identify::ReportMetadata metadata;
  metadata.source = run.bag.empty() ? run.topic : run.bag;
  metadata.update_rate_hz = 1.0 / snapshot.timing.tau0_s;
  const allan::ImpulseScreenReport& screen = run.impulses;
  metadata.events_screened = screen.enabled;
  metadata.event_count = screen.event_count;
  for (const allan::ImpulseEvent& event : screen.events) {
    identify::ReportEvent listed;
    listed.onset_s = seconds_from(event.onset_stamp_ns, screen.first_stamp_ns);
    listed.window_start_s = seconds_from(event.start_stamp_ns, screen.first_stamp_ns);
    listed.window_end_s = seconds_from(event.end_stamp_ns, screen.first_stamp_ns);
    listed.peak_channel = event.peak_channel < kAllanChannelCount ? kAllanChannelNames[event.peak_channel] : "";
    listed.peak_sigma = event.peak_sigma;
    listed.dropped_samples = event.dropped_sample_count;
    metadata.events.push_back(listed);
  }
  const allan::LevelShiftReport& shifts = run.level_shifts;
  metadata.level_shifts_screened = shifts.enabled;
  metadata.level_shift_count = shifts.event_count;
  for (const allan::LevelShiftEvent& shift : shifts.events) {
    identify::ReportLevelShift listed;
    listed.step_s = seconds_from(shift.step_stamp_ns, shifts.first_stamp_ns);
    listed.window_start_s = seconds_from(shift.start_stamp_ns, shifts.first_stamp_ns);
    listed.window_end_s = seconds_from(shift.end_stamp_ns, shifts.first_stamp_ns);
    listed.peak_channel = shift.peak_channel < kAllanChannelCount ? kAllanChannelNames[shift.peak_channel] : "";
    listed.peak_sigma = shift.peak_sigma;
    for (const allan::LevelShiftChannel& channel : shift.channels) {
      if (channel.channel >= kAllanChannelCount) continue;
      listed.shifts.emplace_back(
          std::string(kAllanChannelNames[channel.channel]) + "_" + allan_value_unit(run.input, channel.channel),
          channel.shift);
    }
    listed.masked_samples = shift.masked_sample_count;
    metadata.level_shifts.push_back(listed);
  }
  return metadata;
}

}  // namespace

std::string bootstrap_replicas_problem(int replicas) {
  if (replicas == 0 || replicas >= 2) return "";
  return "must be 0 (sigmas from the fit's moment covariance) or at least 2 (a bootstrap), not " +
         std::to_string(replicas);
}

std::string partial_curves_file_name(const std::string& channel_name) {
  return "noise_partial_" + channel_name + ".csv";
}

double record_length_s(const allan::StreamingSnapshot& snapshot) {
  return static_cast<double>(snapshot.timing.accepted_sample_count) * snapshot.timing.tau0_s;
}

AllanNoiseReport identify_triads(const AllanRunDescription& run, const allan::StreamingSnapshot& snapshot,
                                 const AllanIdentifyOptions& options) {
  AllanNoiseReport report;
  if (!options.enabled) return report;
  if (!snapshot.warmed_up || !(snapshot.timing.tau0_s > 0.0)) {
    report.problems.push_back("no identification: the run has not warmed up (too few samples to fix tau0)");
    return report;
  }
  for (const SensorKind sensor : kSensors) {
    const std::string name = identify::sensor_prefix(sensor);
    try {
      report.triads.push_back(fit_sensor(sensor, run, snapshot, options));
    } catch (const Cancelled&) {
      throw;  // abandoned, not failed: the caller wanted no result
    } catch (const InputError& error) {
      report.problems.push_back(name + " not identified: record too short or curve unusable (" +
                                std::to_string(record_length_s(snapshot)) + " s of data): " + error.what());
    } catch (const std::exception& error) {
      report.problems.push_back(name + " not identified: the fit failed: " + error.what());
    }
  }
  return report;
}

AllanNoiseReport write_allan_noise_report(const std::string& directory, const AllanRunDescription& run,
                                          const allan::StreamingSnapshot& snapshot,
                                          const AllanIdentifyOptions& options) {
  AllanNoiseReport report = identify_triads(run, snapshot, options);
  if (report.triads.empty()) return report;

  const identify::ReportMetadata metadata = report_metadata(run, snapshot);
  const std::string noise_path = directory + "/noise.yaml";
  identify::write_noise_report(noise_path, report.triads, metadata);
  report.written.push_back(noise_path);

  if (report.triads.size() == kSensors.size()) {
    report.kalibr = identify::kalibr_noise(report.triads[0], report.triads[1], metadata.update_rate_hz, run.topic);
    const std::string kalibr_path = directory + "/kalibr_imu.yaml";
    identify::write_kalibr_imu_yaml(kalibr_path, *report.kalibr);
    report.written.push_back(kalibr_path);
    const std::string chain_path = directory + "/kalibr_imu_chain.yaml";
    identify::write_kalibr_imu_chain_yaml(chain_path, *report.kalibr);
    report.written.push_back(chain_path);
  } else {
    report.problems.push_back(
        "no kalibr_imu.yaml or kalibr_imu_chain.yaml: they need both the gyro and the accelerometer identified");
  }

  for (const identify::TriadFit& triad : report.triads) {
    const auto curves = oadev_curves(snapshot, triad.sensor);
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const std::string path =
          directory + "/" + partial_curves_file_name(identify::axis_name(triad.sensor, static_cast<int>(axis)));
      identify::write_partial_curves_csv(path, identify::partial_curves(triad.axes[axis], curves[axis]),
                                         identify::rate_unit_key(triad.sensor));
      report.written.push_back(path);
    }
  }
  return report;
}

std::string format_identification_summary(const AllanIdentifyOptions& options, const AllanNoiseReport& report) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "identification" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "enabled" << YAML::Value << options.enabled;
  if (options.enabled) {
    out << YAML::Key << "sigma_source" << YAML::Value
        << identify::sigma_source_name(options.bootstrap_replicas > 0 ? identify::SigmaSource::kBootstrap
                                                                      : identify::SigmaSource::kMomentCovariance);
    out << YAML::Key << "bootstrap_replicas" << YAML::Value << options.bootstrap_replicas;
    out << YAML::Key << "identified" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const auto& triad : report.triads) out << identify::sensor_prefix(triad.sensor);
    out << YAML::EndSeq;
    out << YAML::Key << "problems" << YAML::Value << YAML::BeginSeq;
    for (const auto& problem : report.problems) out << problem;
    out << YAML::EndSeq;
  }
  out << YAML::EndMap << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace pipeline
}  // namespace imu_lab
