// Each noise process alone, and a mixture: the batch reference's overlapping AVAR of generated
// interval averages against the analytic AVAR (doc/models.md), at octave-spaced taus over
// 3-4 decades, all points inside Bonferroni chi-squared bounds at 99.7 % family-wise.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "imu_lab/noise/analytic_avar.h"
#include "imu_lab/noise/flicker_bank.h"
#include "imu_lab/noise/make_noise_process.h"
#include "imu_lab/noise/normal_stream.h"
#include "imu_lab/noise/pulse_quantizer.h"
#include "test_noise_avar_check.h"

namespace imu_lab {
namespace noise {
namespace {

constexpr double kTau0 = 0.01;
constexpr std::size_t kSamples = std::size_t(1) << 20;  // 2.9 h at 100 Hz
constexpr int kMaxFactor = 1 << 14;                     // tau up to 164 s: 4.2 decades

std::vector<double> generate(NoiseProcess& process, std::size_t count, double tau0) {
  std::size_t k = 0;
  return test::collect(count, [&]() { return process.next_interval_average(tau0 * k++, tau0); });
}

// Independent processes summed sample by sample; their AVARs add.
struct Mixture {
  std::vector<std::unique_ptr<NoiseProcess>> processes;
  std::vector<double> generate(std::size_t count, double tau0) {
    std::size_t k = 0;
    return test::collect(count, [&]() {
      double sum = 0.0;
      for (auto& process : processes) sum += process->next_interval_average(tau0 * k, tau0);
      ++k;
      return sum;
    });
  }
  double allan_variance(double tau, double tau0) const {
    double avar = 0.0;
    for (const auto& process : processes) avar += process->allan_variance(tau, tau0);
    return avar;
  }
};

void expect_matches(const std::vector<double>& rates, double tau0, const std::function<double(double)>& expected,
                    int m_min, int m_max, const char* what) {
  const test::AvarCheck check = test::check_avar(rates, tau0, expected, m_min, m_max);
  EXPECT_TRUE(check.passed()) << what << "\n" << check.table;
  std::printf("[avar] %-28s points %2d  worst |ratio-1|/sqrt(2/edf) = %.2f (ratio %.3f)  rejected %d\n", what,
              check.point_count, check.worst_normalised_deviation, check.worst_ratio, check.rejected_points);
}

void expect_process_matches(const ProcessParameters& parameters, std::uint64_t seed, int m_min = 1,
                            int m_max = kMaxFactor) {
  auto process = make_noise_process(parameters, seed);
  const auto rates = generate(*process, kSamples, kTau0);
  expect_matches(
      rates, kTau0, [&](double tau) { return process->allan_variance(tau, kTau0); }, m_min, m_max,
      process->kind().c_str());
}

TEST(NoiseAvar, WhiteRate) { expect_process_matches(WhiteRateParameters{1e-3}, 11); }

TEST(NoiseAvar, MarkovWithCorrelationTimeTwoSamples) {
  expect_process_matches(MarkovParameters{1e-2, 2.0 * kTau0}, 12);
}

TEST(NoiseAvar, MarkovWithCorrelationTimeOneSecond) { expect_process_matches(MarkovParameters{1e-3, 1.0}, 13); }

TEST(NoiseAvar, RateRandomWalk) { expect_process_matches(RandomWalkParameters{1e-4}, 14); }

TEST(NoiseAvar, WhiteRateThroughSensorBandwidth) {
  // A 20 Hz first-order anti-alias filter at 100 Hz: exact interval averages of the filtered
  // signal follow eq. 5.7 with T_c = 1/(2 pi 20 Hz), q_c = N / T_c (the leftmost points pulled
  // below N^2 / tau, doc/models.md).
  auto process = make_noise_process(WhiteRateParameters{1e-3}, 27, 20.0);
  const auto rates = generate(*process, kSamples, kTau0);
  const double tc = 1.0 / (2.0 * 3.14159265358979323846 * 20.0);
  expect_matches(
      rates, kTau0, [&](double tau) { return markov_avar(1e-3 / tc, tc, tau); }, 1, kMaxFactor,
      "white through 20 Hz bandwidth");
  EXPECT_LT(markov_avar(1e-3 / tc, tc, kTau0), 0.75 * white_rate_avar(1e-3, kTau0));
}

TEST(NoiseAvar, WhiteAngleQuantizationModel) { expect_process_matches(WhiteAngleParameters{2e-6, 0.0}, 15); }

TEST(NoiseAvar, WhiteNoiseInAngle) { expect_process_matches(WhiteAngleParameters{0.0, 3e-6}, 16); }

TEST(NoiseAvar, BiasInstabilityBankAgainstEquation53) {
  // Claimed range [0.1, 1e4] s with f0 = 10 Hz; the data resolve 0.16 .. 164 s (3 decades).
  const BiasInstabilityParameters parameters{1e-4, 10.0, 0.1, 1e4};
  auto process = make_noise_process(parameters, 17);
  const auto rates = generate(*process, kSamples, kTau0);
  expect_matches(
      rates, kTau0, [&](double tau) { return bias_instability_avar(1e-4, 10.0, tau); }, 16, kMaxFactor,
      "bias_instability vs eq. 5.3");
}

TEST(NoiseAvar, BankTracksEquation53OverClaimedRange) {
  for (double tau_max : {1e2, 1e4, 1e6}) {
    const FlickerBankDesign design = design_flicker_bank({2e-5, 1.0, 1.0, tau_max});
    EXPECT_LT(design.max_relative_error, kFlickerBankTolerance) << tau_max;
    std::printf("[bank] f0 = 1 Hz, tau in [1, %g] s: %zu poles, max |AVAR_bank/eq5.3 - 1| = %.4f\n", tau_max,
                design.corner_frequencies_hz.size(), design.max_relative_error);
  }
  // Below ~1/f0 the sharp cutoff of eq. 5.3 cannot be followed: the design is refused.
  EXPECT_THROW(design_flicker_bank({2e-5, 1.0, 0.1, 1e3}), std::invalid_argument);
}

TEST(NoiseAvar, ZeroDcFamilySquaredFrequency) {
  const ZeroDcFamilyParameters parameters{2, 1e-6, 0.05};
  auto process = make_noise_process(parameters, 18);
  const auto rates = generate(*process, kSamples / 4, kTau0);
  expect_matches(
      rates, kTau0, [&](double tau) { return zero_dc_family_avar(2, 1e-6, 0.05, tau); }, 1, kMaxFactor / 4,
      "zero_dc n=2 vs table 7.2");
  // The FIR realisation's own AVAR is within 1e-3 of table 7.2 (tau0 .. 1000 tau0).
  for (int m : {1, 4, 16, 64, 256, 1000}) {
    const double tau = m * kTau0;
    EXPECT_NEAR(process->allan_variance(tau, kTau0) / zero_dc_family_avar(2, 1e-6, 0.05, tau), 1.0, 1e-3);
  }
}

TEST(NoiseAvar, PhysicalPulseQuantizationOfWhiteNoise) {
  // White noise moves the angle by ~5 pulses per sample, so rounding is white, Q = S/sqrt(12).
  const double density = 1e-4, pulse = density * std::sqrt(kTau0) / 5.0;
  auto white = make_noise_process(WhiteRateParameters{density}, 19);
  PulseQuantizer quantizer(pulse);
  std::size_t k = 0;
  const auto rates = test::collect(
      kSamples, [&]() { return quantizer.quantize(white->next_interval_average(kTau0 * k++, kTau0) * kTau0) / kTau0; });
  expect_matches(
      rates, kTau0, [&](double tau) { return white_rate_avar(density, tau) + pulse_quantization_avar(pulse, tau); }, 1,
      kMaxFactor, "pulses + white");
}

TEST(NoiseAvar, MixtureOfAllStochasticProcesses) {
  Mixture mixture;
  mixture.processes.push_back(make_noise_process(WhiteRateParameters{3e-4}, 21));
  mixture.processes.push_back(make_noise_process(MarkovParameters{5e-3, 2.0 * kTau0}, 22));
  mixture.processes.push_back(make_noise_process(MarkovParameters{2e-4, 3.0}, 23));
  mixture.processes.push_back(make_noise_process(BiasInstabilityParameters{2e-5, 10.0, 0.1, 1e4}, 24));
  mixture.processes.push_back(make_noise_process(RandomWalkParameters{3e-6}, 25));
  mixture.processes.push_back(make_noise_process(WhiteAngleParameters{1e-6, 0.0}, 26));
  const auto rates = mixture.generate(kSamples, kTau0);
  expect_matches(
      rates, kTau0, [&](double tau) { return mixture.allan_variance(tau, kTau0); }, 1, kMaxFactor, "mixture");
}

TEST(NoiseAvar, SampleRateDoesNotChangeTheAvarWhereResolved) {
  // White + Markov + random walk at 100 Hz and 400 Hz: both follow the same rate-independent
  // curve from 0.04 s (resolved by both) up.
  for (double tau0 : {0.01, 0.0025}) {
    Mixture mixture;
    mixture.processes.push_back(make_noise_process(WhiteRateParameters{3e-4}, 31));
    mixture.processes.push_back(make_noise_process(MarkovParameters{3e-3, 0.05}, 32));
    mixture.processes.push_back(make_noise_process(RandomWalkParameters{2e-5}, 33));
    const auto rates = mixture.generate(kSamples, tau0);
    const int m_min = static_cast<int>(std::lround(0.04 / tau0));
    expect_matches(
        rates, tau0,
        [&](double tau) {
          return white_rate_avar(3e-4, tau) + markov_avar(3e-3, 0.05, tau) + random_walk_avar(2e-5, tau);
        },
        m_min, m_min * 1024, tau0 == 0.01 ? "100 Hz" : "400 Hz");
  }
}

}  // namespace
}  // namespace noise
}  // namespace imu_lab
