#include "imu_lab/emulator/sensor_channel.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <map>
#include <stdexcept>
#include <variant>

#include "imu_lab/noise/make_noise_process.h"
#include "imu_lab/noise/normal_stream.h"

namespace imu_lab {
namespace emulator {

namespace {
const char* const kAxisNames[3] = {"x", "y", "z"};
}

TriadChannel::TriadChannel(const TriadErrorModel& model, const std::string& triad_name, std::uint64_t seed)
    : model_(model),
      scale_misalignment_(model.scale_misalignment_matrix()),
      quantizers_{noise::PulseQuantizer(model.pulse_weight), noise::PulseQuantizer(model.pulse_weight),
                  noise::PulseQuantizer(model.pulse_weight)} {
  noise::NormalStream turn_on(noise::stream_seed(seed, triad_name + ".turn_on_bias"));
  for (int axis = 0; axis < 3; ++axis) {
    turn_on_bias_[axis] = model.bias_turn_on_sigma[axis] * turn_on.next();
    // Streams are numbered within their kind, so a process's deviates do not depend on
    // which other kinds the profile lists.
    std::map<std::string, int> kind_count;
    for (const auto& parameters : model.noise_per_axis[axis]) {
      const std::string kind = noise::process_kind(parameters);
      const std::string stream =
          triad_name + "." + kAxisNames[axis] + "." + kind + "#" + std::to_string(kind_count[kind]++);
      if (white_index_[axis] < 0 && std::holds_alternative<noise::WhiteRateParameters>(parameters)) {
        white_index_[axis] = static_cast<int>(processes_[axis].size());
        white_density_[axis] = std::get<noise::WhiteRateParameters>(parameters).density_per_sqrt_hz;
      }
      processes_[axis].push_back(
          noise::make_noise_process(parameters, noise::stream_seed(seed, stream), model.bandwidth_hz));
    }
  }
  if (model.white_rate_correlation != Eigen::Matrix3d::Identity()) {
    Eigen::LLT<Eigen::Matrix3d> cholesky(model.white_rate_correlation);
    if (cholesky.info() != Eigen::Success) {
      throw std::invalid_argument(triad_name + ": white_rate_correlation is not positive definite");
    }
    white_factor_ = cholesky.matrixL();
    correlate_white_ = true;
  }
}

Eigen::Vector3d TriadChannel::response(const Eigen::Vector3d& w, const Eigen::Vector3d& thermal_scale) const {
  const Eigen::Vector3d w2 = w.cwiseProduct(w);
  Eigen::Vector3d r = scale_misalignment_ * w + thermal_scale.cwiseProduct(w) +
                      model_.quadratic_nonlinearity_per_unit.cwiseProduct(w2) +
                      model_.cubic_nonlinearity_per_unit2.cwiseProduct(w2.cwiseProduct(w)) +
                      0.5e-6 * model_.scale_factor_asymmetry_ppm.cwiseProduct(w.cwiseAbs());
  for (int i = 0; i < 3; ++i) {
    if (std::abs(r[i]) < model_.dead_zone[i]) r[i] = 0.0;
  }
  return r;
}

Eigen::Vector3d TriadChannel::measure(const Eigen::Vector3d& true_average,
                                      const Eigen::Vector3d& specific_force_average, double elapsed_start_s,
                                      double interval_s) {
  return measure(true_average, specific_force_average, elapsed_start_s, interval_s,
                 {model_.thermal.reference_temperature_c, 0.0});
}

Eigen::Vector3d TriadChannel::measure(const Eigen::Vector3d& true_average,
                                      const Eigen::Vector3d& specific_force_average, double elapsed_start_s,
                                      double interval_s, const SensorTemperature& temperature) {
  const ThermalSensitivity& thermal = model_.thermal;
  const Eigen::Vector3d thermal_scale = 1e-6 * thermal.scale_factor_ppm(temperature.temperature_c, temperature.rate_c_s,
                                                                        temperature.second_temperature_c);
  Eigen::Vector3d output =
      total_bias() + thermal.bias(temperature.temperature_c, temperature.rate_c_s, temperature.second_temperature_c) +
      response(true_average, thermal_scale) + model_.g_sensitivity * specific_force_average;
  Eigen::Vector3d white = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t p = 0; p < processes_[axis].size(); ++p) {
      const double value = processes_[axis][p]->next_interval_average(elapsed_start_s, interval_s);
      if (correlate_white_ && static_cast<int>(p) == white_index_[axis]) {
        white[axis] = value;
      } else {
        output[axis] += value;
      }
    }
  }
  if (correlate_white_) {
    // Each axis's white sample is its density times a unit deviate stream (filtered alike on all
    // axes): mix the unit streams with the Cholesky factor, then restore the densities.
    Eigen::Vector3d unit = Eigen::Vector3d::Zero();
    for (int axis = 0; axis < 3; ++axis) {
      if (white_density_[axis] > 0.0) unit[axis] = white[axis] / white_density_[axis];
    }
    output += white_density_.cwiseProduct(white_factor_ * unit);
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (model_.pulse_weight > 0.0) {
      output[axis] = quantizers_[axis].quantize(output[axis] * interval_s) / interval_s;
    }
    const double lsb = model_.output_lsb[axis];
    if (lsb > 0.0) output[axis] = std::round(output[axis] / lsb) * lsb;
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
    // Rounding to the output LSB: uniform over one step.
    variance[axis] += model_.output_lsb[axis] * model_.output_lsb[axis] / 12.0;
  }
  return variance;
}

std::array<std::vector<double>, 3> rates_at_rest(const TriadErrorModel& model, const std::string& triad_name,
                                                 double rate_hz, double duration_s, std::uint64_t seed) {
  TriadChannel channel(model, triad_name, seed);
  const double interval_s = 1.0 / rate_hz;
  const long long count = std::llround(duration_s * rate_hz);
  std::array<std::vector<double>, 3> rates;
  for (auto& axis : rates) axis.resize(count);
  for (long long k = 0; k < count; ++k) {
    const Eigen::Vector3d sample =
        channel.measure(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), k * interval_s, interval_s);
    for (int axis = 0; axis < 3; ++axis) rates[axis][k] = sample[axis];
  }
  return rates;
}

}  // namespace emulator
}  // namespace imu_lab
