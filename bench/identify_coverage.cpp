// Long studies of the noise identification (not run by CI).
//
//   identify_coverage coverage [seeds=40] [replicas=20]
//     Case 1 (the MEMS mixture of test_identify_mems_mixture.cpp) over many seeds: the share of
//     estimates within 1 reported sigma of the truth, for the Ceres-covariance sigma and for the
//     bootstrap sigma (target: 50 % to 85 %, ~68 % if the sigmas mean what they say).
//   identify_coverage rlg [hours=150] [rate_hz=10] [replicas=0] [profile=config/sensors/rlg_navigation.yaml]
//     The navigation-grade ring-laser gyro profile (x axis, at rest): B's estimate and sigma, and
//     the record length the fit says B needs for 15 %. The profile's 1 arcsec pulses are replaced
//     by their white-angle model Q = S / sqrt(12) (a dithered RLG): undithered at rest the angle
//     moves ~0.02 pulse per sample at 10 Hz and the rounding error is a slow sawtooth, not the
//     white angle noise any AVAR term describes.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/emulator/sensor_channel.h"
#include "imu_lab/emulator/sensor_profile.h"
#include "imu_lab/identify/bootstrap.h"
#include "imu_lab/identify/fit.h"
#include "imu_lab/identify/record_length.h"

using namespace imu_lab;
using namespace imu_lab::identify;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Axis-x rates of a triad channel at rest.
std::vector<double> emulate_x(const emulator::TriadErrorModel& model, double rate_hz,
                              double duration_s, std::uint64_t seed) {
  emulator::TriadChannel channel(model, "gyro", seed);
  const double interval_s = 1.0 / rate_hz;
  const long long count = static_cast<long long>(duration_s * rate_hz);
  std::vector<double> rates(count);
  for (long long k = 0; k < count; ++k) {
    rates[k] = channel.measure(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), k * interval_s, interval_s)[0];
  }
  return rates;
}

FitResult fit_rates(const std::vector<double>& rates, double rate_hz) {
  const double duration_s = rates.size() / rate_hz;
  const auto curve = allan::evaluate_frequency(allan::Statistic::kOverlappingAllan, rates,
                                               1.0 / rate_hz, octave_averaging_factors(rates.size()));
  return fit_noise_model(curve, 1.0 / rate_hz, duration_s);
}

struct Truth {
  const char* name;
  double value;
};

int run_coverage(int seeds, int replicas) {
  // Case 1, as in test_identify_mems_mixture.cpp.
  const double rate_hz = 10.0, duration_s = 24.0 * 3600.0;
  const std::vector<Truth> truths = {{"white_angle", 4.4e-6}, {"white_rate", 4.4e-5},
                                     {"bias_instability", 1.49e-5}, {"random_walk", 3.2e-5}};
  emulator::TriadErrorModel model;
  model.noise_per_axis[0] = {
      noise::WhiteRateParameters{4.4e-5},
      noise::BiasInstabilityParameters{1.49e-5, rate_hz / 2.0, 2.0 / rate_hz, duration_s},
      noise::RandomWalkParameters{3.2e-5}, noise::WhiteAngleParameters{4.4e-6, 0.0}};
  std::vector<int> within_ceres(truths.size(), 0), within_bootstrap(truths.size(), 0);
  std::vector<int> found(truths.size(), 0);
  std::vector<double> relative_sigma_sum(truths.size(), 0.0);
  const auto start = std::chrono::steady_clock::now();
  for (int seed = 1; seed <= seeds; ++seed) {
    FitResult fit = fit_rates(emulate_x(model, rate_hz, duration_s, 1000 + seed), rate_hz);
    std::vector<double> ceres_sigma(truths.size(), NAN);
    for (size_t i = 0; i < truths.size(); ++i) {
      const TermEstimate* term = fit.find(truths[i].name);
      if (term != nullptr && term->status != TermStatus::kAbsent) ceres_sigma[i] = term->amplitude.sigma;
    }
    if (replicas > 1) apply_bootstrap(bootstrap_uncertainty(fit, {replicas, 77ULL * seed}), &fit);
    std::printf("seed %3d:", seed);
    for (size_t i = 0; i < truths.size(); ++i) {
      const TermEstimate* term = fit.find(truths[i].name);
      if (term == nullptr || term->status == TermStatus::kAbsent) {
        std::printf("  %s absent (bound %.3g)", truths[i].name, term ? term->amplitude.upper_bound : NAN);
        continue;
      }
      ++found[i];
      const double error = std::abs(term->amplitude.value - truths[i].value);
      within_ceres[i] += error < ceres_sigma[i];
      within_bootstrap[i] += error < term->amplitude.sigma;
      relative_sigma_sum[i] += term->amplitude.sigma / term->amplitude.value;
      std::printf("  %s %.3g+-%.2g", truths[i].name, term->amplitude.value, term->amplitude.sigma);
    }
    std::printf("  (%.0f s)\n", seconds_since(start));
    std::fflush(stdout);
  }
  int total_ceres = 0, total_bootstrap = 0, total = 0;
  std::printf("\nterm               found  within 1 sigma: ceres  bootstrap  mean rel. sigma (bootstrap)\n");
  for (size_t i = 0; i < truths.size(); ++i) {
    std::printf("%-18s %3d/%-3d %17.0f %%  %8.0f %%  %8.1f %%\n", truths[i].name, found[i], seeds,
                100.0 * within_ceres[i] / seeds, 100.0 * within_bootstrap[i] / seeds,
                found[i] ? 100.0 * relative_sigma_sum[i] / found[i] : NAN);
    total_ceres += within_ceres[i];
    total_bootstrap += within_bootstrap[i];
    total += seeds;
  }
  std::printf("all terms: within 1 sigma %.1f %% (ceres covariance), %.1f %% (bootstrap)\n",
              100.0 * total_ceres / total, 100.0 * total_bootstrap / total);
  return 0;
}

int run_rlg(double hours, double rate_hz, int replicas, const std::string& profile_path) {
  emulator::SensorProfile profile = emulator::load_sensor_profile(profile_path);
  emulator::TriadErrorModel gyro = profile.gyro;
  const double duration_s = hours * 3600.0;
  double true_b = 0.0, true_n = 0.0, true_q = gyro.pulse_weight / std::sqrt(12.0);
  for (auto& process : gyro.noise_per_axis[0]) {
    if (auto* bias = std::get_if<noise::BiasInstabilityParameters>(&process)) {
      // The profile claims eq. 5.3 up to its tau range; extend it over the whole record.
      bias->tau_max_s = std::max(bias->tau_max_s, duration_s);
      true_b = bias->coefficient;
    }
    if (auto* white = std::get_if<noise::WhiteRateParameters>(&process)) {
      true_n = white->density_per_sqrt_hz;
    }
  }
  if (gyro.pulse_weight > 0.0) {
    gyro.noise_per_axis[0].push_back(
        noise::WhiteAngleParameters{gyro.pulse_weight / std::sqrt(12.0), 0.0});
    gyro.pulse_weight = 0.0;
  }
  const auto start = std::chrono::steady_clock::now();
  const auto rates = emulate_x(gyro, rate_hz, duration_s, 1);
  std::printf("emulated %.0f h at %.0f Hz in %.0f s\n", hours, rate_hz, seconds_since(start));
  FitResult fit = fit_rates(rates, rate_hz);
  std::printf("fitted in %.1f s; quality: deviance %.1f on %d dof, p = %.3f\n", seconds_since(start),
              fit.quality.deviance, fit.quality.degrees_of_freedom, fit.quality.p_value);
  const auto report = [&](const char* label) {
    std::printf("%s\n", label);
    for (const TermEstimate& term : fit.terms) {
      std::printf("  %-18s %-13s value %.4g sigma %.3g (%.1f %%, %s) bound %.3g shape %.3g\n",
                  term.name.c_str(), term_status_name(term.status).c_str(), term.amplitude.value,
                  term.amplitude.sigma, 100.0 * term.amplitude.sigma / term.amplitude.value,
                  sigma_source_name(term.sigma_source).c_str(), term.amplitude.upper_bound,
                  term.shape.value);
    }
    const TermEstimate* bias = fit.find("bias_instability");
    if (bias != nullptr && bias->status != TermStatus::kAbsent) {
      std::printf("  B: truth %.3g rad/s, estimate %.3g +- %.2g; record needed for 15 %%: %.1f h\n",
                  true_b, bias->amplitude.value, bias->amplitude.sigma,
                  required_record_length_s(fit, "bias_instability", 0.15) / 3600.0);
    }
  };
  std::printf("truth: Q %.3g rad, N %.3g rad/s/sqrt(Hz), B %.3g rad/s\n", true_q, true_n, true_b);
  std::printf("graphical: N slope reading at 1 s %.3g, B flat tangent %.3g\n",
              fit.graphical.white_rate_at_1s, fit.graphical.bias_instability_from_minimum);
  report("Ceres covariance:");
  if (replicas > 1) {
    apply_bootstrap(bootstrap_uncertainty(fit, {replicas, 5}), &fit);
    report("bootstrap:");
  }
  for (const auto& warning : fit.warnings) std::printf("  warning: %s\n", warning.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "coverage";
  if (mode == "coverage") {
    return run_coverage(argc > 2 ? std::atoi(argv[2]) : 40, argc > 3 ? std::atoi(argv[3]) : 20);
  }
  if (mode == "rlg") {
    return run_rlg(argc > 2 ? std::atof(argv[2]) : 150.0, argc > 3 ? std::atof(argv[3]) : 10.0,
                   argc > 4 ? std::atoi(argv[4]) : 0,
                   argc > 5 ? argv[5] : "config/sensors/rlg_navigation.yaml");
  }
  std::fprintf(stderr, "usage: identify_coverage coverage [seeds] [replicas] | rlg [hours] [rate_hz] [replicas] [profile]\n");
  return 2;
}
