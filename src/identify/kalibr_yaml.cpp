#include "imu_lab/identify/kalibr_yaml.h"

#include <cmath>
#include <sstream>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/identify/white_equivalent.h"

namespace imu_lab {
namespace identify {

namespace {

void write_entry(std::ostringstream& out, const std::string& key, double value, const std::string& comment) {
  out << key << ": " << value << "  # " << comment << "\n";
}

void write_pair(std::ostringstream& out, const std::string& sensor, const std::string& rate_unit,
                const KalibrValue& density, const KalibrValue& walk, double rate_hz) {
  const auto flag = [](const KalibrValue& v) {
    return v.is_upper_bound ? " UPPER BOUND: the fit could not constrain it" : "";
  };
  write_entry(out, sensor + "_noise_density", density.value,
              "[" + rate_unit + "/sqrt(Hz)] continuous, axis " + std::to_string(density.axis) + flag(density));
  write_entry(out, sensor + "_random_walk", walk.value,
              "[" + rate_unit + "/s/sqrt(Hz)] continuous, axis " + std::to_string(walk.axis) + flag(walk));
  write_entry(out, sensor + "_noise_density_discrete", density.value * std::sqrt(rate_hz),
              "[" + rate_unit + "] per sample = density * sqrt(update_rate)");
  write_entry(out, sensor + "_random_walk_discrete", walk.value / std::sqrt(rate_hz),
              "[" + rate_unit + "] per sample = random_walk / sqrt(update_rate)");
  out << sensor << "_noise_density_is_upper_bound: " << (density.is_upper_bound ? "true" : "false") << "\n";
  out << sensor << "_random_walk_is_upper_bound: " << (walk.is_upper_bound ? "true" : "false") << "\n";
}

// One axis's candidate: the white-equivalent density for N (white_equivalent.h), else the
// term's value, or its upper bound when the fit found it absent. NaN when there is none.
KalibrValue axis_kalibr_value(const FitResult& fit, TermKind kind) {
  KalibrValue candidate;
  candidate.value = std::nan("");
  if (kind == TermKind::kWhiteRate) {
    candidate.value = white_equivalent_density(fit);
    if (std::isfinite(candidate.value)) return candidate;
  }
  const TermEstimate* term = fit.find(term_kind_name(kind));
  if (term == nullptr) return candidate;
  candidate.is_upper_bound = term->status != TermStatus::kPresent;
  candidate.value = candidate.is_upper_bound ? term->amplitude.upper_bound : term->amplitude.value;
  return candidate;
}

}  // namespace

KalibrValue kalibr_value(const TriadFit& triad, TermKind kind) {
  KalibrValue result;
  result.value = -1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const KalibrValue candidate = axis_kalibr_value(triad.axes[axis], kind);
    if (std::isfinite(candidate.value) && candidate.value > result.value) {
      result = candidate;
      result.axis = axis;
    }
  }
  if (result.value < 0.0) {  // the term was not a candidate: nothing known, say so
    result.value = 0.0;
    result.is_upper_bound = true;
  }
  return result;
}

KalibrImuNoise kalibr_noise(const TriadFit& gyro, const TriadFit& accelerometer, double update_rate_hz,
                            const std::string& rostopic) {
  KalibrImuNoise noise;
  noise.gyroscope_noise_density = kalibr_value(gyro, TermKind::kWhiteRate);
  noise.gyroscope_random_walk = kalibr_value(gyro, TermKind::kRandomWalk);
  noise.accelerometer_noise_density = kalibr_value(accelerometer, TermKind::kWhiteRate);
  noise.accelerometer_random_walk = kalibr_value(accelerometer, TermKind::kRandomWalk);
  noise.update_rate_hz = update_rate_hz;
  noise.rostopic = rostopic;
  return noise;
}

std::string format_kalibr_imu_yaml(const KalibrImuNoise& noise) {
  std::ostringstream out;
  out.precision(17);
  out << "# IMU noise model for Kalibr, identified by imu_lab (Allan-variance fit).\n"
         "# Continuous-time densities (Kalibr's convention); *_discrete are the per-sample values\n"
         "# at update_rate. One value per sensor: the largest over its axes. The noise density\n"
         "# is the white-equivalent one: N plus, in power, any Markov term whose T_c is below\n"
         "# twice tau0 (white noise behind the sensor's low-pass; see noise.yaml's warnings).\n";
  write_pair(out, "accelerometer", "m/s^2", noise.accelerometer_noise_density, noise.accelerometer_random_walk,
             noise.update_rate_hz);
  write_pair(out, "gyroscope", "rad/s", noise.gyroscope_noise_density, noise.gyroscope_random_walk,
             noise.update_rate_hz);
  out << "rostopic: " << noise.rostopic << "  # " << rostopic_reminder(noise.rostopic) << "\n";
  out << "update_rate: " << noise.update_rate_hz << "  # [Hz] measured\n";
  return out.str();
}

void write_kalibr_imu_yaml(const std::string& path, const KalibrImuNoise& noise) {
  write_file_atomically(path, format_kalibr_imu_yaml(noise));
}

std::string rostopic_reminder(const std::string& rostopic) {
  return "the recording's topic" + std::string(rostopic.empty() ? "" : " (" + rostopic + ")") +
         ": set it to the one your IMU publishes on";
}

void write_imu_chain_node(std::ostream& out, const ImuChainNode& node) {
  const auto matrix = [&out](const char* key, const Eigen::Matrix3d& m) {
    out << "  " << key << ":\n";
    for (int row = 0; row < 3; ++row) out << "    - [" << m(row, 0) << ", " << m(row, 1) << ", " << m(row, 2) << "]\n";
  };
  out << "imu0:\n";
  out << "  T_i_b:\n    - [1.0, 0.0, 0.0, 0.0]\n    - [0.0, 1.0, 0.0, 0.0]\n    - [0.0, 0.0, 1.0, 0.0]\n"
      << "    - [0.0, 0.0, 0.0, 1.0]\n";
  out << "  accelerometer_noise_density: " << node.accelerometer_noise_density << "\n";
  out << "  accelerometer_random_walk: " << node.accelerometer_random_walk << "\n";
  out << "  gyroscope_noise_density: " << node.gyroscope_noise_density << "\n";
  out << "  gyroscope_random_walk: " << node.gyroscope_random_walk << "\n";
  out << "  rostopic: " << node.rostopic << (node.rostopic_comment.empty() ? "" : "  # " + node.rostopic_comment)
      << "\n";
  out << "  time_offset: 0.0\n  update_rate: " << node.update_rate_hz << "\n";
  out << "  model: \"kalibr\"\n";
  matrix("Tw", node.intrinsics.Tw);
  matrix("R_IMUtoGYRO", node.intrinsics.R_IMUtoGYRO);
  matrix("Ta", node.intrinsics.Ta);
  matrix("R_IMUtoACC", node.intrinsics.R_IMUtoACC);
  matrix("Tg", node.intrinsics.Tg);
}

std::string format_kalibr_imu_chain_yaml(const KalibrImuNoise& noise) {
  std::ostringstream out;
  out.precision(17);
  out << "%YAML:1.0\n"
         "# IMU noise model for OpenVINS (its relative_config_imu file), identified by imu_lab's allan:\n"
         "# the values of kalibr_imu.yaml beside it (continuous time, the largest over each sensor's axes;\n"
         "# that file says which are upper bounds). No intrinsics were calibrated: Tw, Ta and the\n"
         "# rotations are identity (fit_calibration's <name>_kalibr_imu_chain.yaml has them).\n";
  ImuChainNode node;
  node.accelerometer_noise_density = noise.accelerometer_noise_density.value;
  node.accelerometer_random_walk = noise.accelerometer_random_walk.value;
  node.gyroscope_noise_density = noise.gyroscope_noise_density.value;
  node.gyroscope_random_walk = noise.gyroscope_random_walk.value;
  node.rostopic = noise.rostopic;
  node.rostopic_comment = rostopic_reminder(noise.rostopic);
  node.update_rate_hz = noise.update_rate_hz;
  write_imu_chain_node(out, node);
  return out.str();
}

void write_kalibr_imu_chain_yaml(const std::string& path, const KalibrImuNoise& noise) {
  write_file_atomically(path, format_kalibr_imu_chain_yaml(noise));
}

}  // namespace identify
}  // namespace imu_lab
