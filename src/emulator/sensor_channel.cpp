#include "imu_lab/emulator/sensor_channel.h"

#include <map>

#include "imu_lab/noise/make_noise_process.h"
#include "imu_lab/noise/normal_stream.h"

namespace imu_lab {
namespace emulator {

namespace {
const char* const kAxisNames[3] = {"x", "y", "z"};
}

TriadChannel::TriadChannel(const TriadErrorModel& model, const std::string& triad_name,
                           std::uint64_t seed)
    : model_(model),
      scale_misalignment_(model.scale_misalignment_matrix()),
      quantizers_{noise::PulseQuantizer(model.pulse_weight),
                  noise::PulseQuantizer(model.pulse_weight),
                  noise::PulseQuantizer(model.pulse_weight)} {
  noise::NormalStream turn_on(noise::stream_seed(seed, triad_name + ".turn_on_bias"));
  for (int axis = 0; axis < 3; ++axis) {
    turn_on_bias_[axis] = model.bias_turn_on_sigma[axis] * turn_on.next();
    // Streams are numbered within their kind, so a process's deviates do not depend on
    // which other kinds the profile lists.
    std::map<std::string, int> kind_count;
    for (const auto& parameters : model.noise_per_axis[axis]) {
      const std::string kind = noise::process_kind(parameters);
      const std::string stream = triad_name + "." + kAxisNames[axis] + "." + kind + "#" +
                                 std::to_string(kind_count[kind]++);
      processes_[axis].push_back(noise::make_noise_process(
          parameters, noise::stream_seed(seed, stream), model.bandwidth_hz));
    }
  }
}

Eigen::Vector3d TriadChannel::measure(const Eigen::Vector3d& true_average,
                                      const Eigen::Vector3d& specific_force_average,
                                      double elapsed_start_s, double interval_s) {
  return measure(true_average, specific_force_average, elapsed_start_s, interval_s,
                 {model_.thermal.reference_temperature_c, 0.0});
}

Eigen::Vector3d TriadChannel::measure(const Eigen::Vector3d& true_average,
                                      const Eigen::Vector3d& specific_force_average,
                                      double elapsed_start_s, double interval_s,
                                      const SensorTemperature& temperature) {
  const ThermalSensitivity& thermal = model_.thermal;
  const Eigen::Vector3d thermal_scale =
      1e-6 * thermal.scale_factor_ppm(temperature.temperature_c, temperature.rate_c_s);
  Eigen::Vector3d output = total_bias() + thermal.bias(temperature.temperature_c, temperature.rate_c_s) +
                           scale_misalignment_ * true_average +
                           thermal_scale.cwiseProduct(true_average) +
                           model_.quadratic_nonlinearity_per_unit.cwiseProduct(
                               true_average.cwiseProduct(true_average)) +
                           model_.g_sensitivity * specific_force_average;
  for (int axis = 0; axis < 3; ++axis) {
    for (auto& process : processes_[axis]) {
      output[axis] += process->next_interval_average(elapsed_start_s, interval_s);
    }
    if (model_.pulse_weight > 0.0) {
      output[axis] = quantizers_[axis].quantize(output[axis] * interval_s) / interval_s;
    }
  }
  return output;
}

Eigen::Vector3d TriadChannel::sample_variance(double interval_s) const {
  Eigen::Vector3d variance = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < 3; ++axis) {
    for (const auto& process : processes_[axis]) variance[axis] += process->sample_variance(interval_s);
    // Emitted increment error = carry before - carry after, two independent U(0, S) residues.
    const double s = model_.pulse_weight;
    variance[axis] += s * s / (6.0 * interval_s * interval_s);
  }
  return variance;
}

}  // namespace emulator
}  // namespace imu_lab
