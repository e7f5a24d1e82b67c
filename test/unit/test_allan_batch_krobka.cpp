// Krobka's dispersions (Krobka 2015, eq. 5.10): the Allan/Hadamard variance with the squared mean
// difference removed. A deterministic drift that AVAR (or HVAR) keeps is removed entirely,
// while on noise alone the dispersion and the variance agree within their confidence bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/allan/confidence.h"
#include "imu_lab/allan/edf.h"

namespace imu_lab {
namespace allan {
namespace {

constexpr double kTau0S = 0.01;

// Rate samples as a rate-integrating sensor delivers them: the interval average of R t + c t^2.
std::vector<double> drifting_rate(std::size_t count, double ramp_rad_s2, double quadratic_rad_s3) {
  std::vector<double> rate(count);
  for (std::size_t k = 0; k < count; ++k) {
    const double start_s = k * kTau0S, end_s = (k + 1) * kTau0S;
    rate[k] = ramp_rad_s2 * 0.5 * (start_s + end_s) +
              quadratic_rad_s3 * (end_s * end_s * end_s - start_s * start_s * start_s) / (3.0 * kTau0S);
  }
  return rate;
}

void add_white_rate_noise(std::vector<double>& rate, double sigma_rad_s, unsigned seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal(0.0, sigma_rad_s);
  for (double& value : rate) value += normal(generator);
}

// Two-sided chi-squared interval of a variance estimate with white-FM EDF.
DeviationBounds white_fm_bounds(Statistic statistic, double deviation, int m, std::size_t n) {
  const double edf = equivalent_degrees_of_freedom(statistic, 0, m, static_cast<long long>(n));
  return chi_squared_bounds(deviation, edf, 0.99);
}

TEST(AllanBatchKrobka, RateRampGivesAvarRSquaredTauSquaredOverTwoAndNoDispersion) {
  const double ramp_rad_s2 = 2e-3;
  const std::vector<double> phase = phase_from_frequency(drifting_rate(20000, ramp_rad_s2, 0.0), kTau0S);
  for (int m : {1, 10, 100, 1000, 5000}) {
    const double tau_s = m * kTau0S;
    const double expected = ramp_rad_s2 * ramp_rad_s2 * tau_s * tau_s / 2.0;
    EXPECT_NEAR(overlapping_allan_variance(phase, kTau0S, m) / expected, 1.0, 1e-8) << m;
    EXPECT_NEAR(allan_variance(phase, kTau0S, m) / expected, 1.0, 1e-8) << m;
    EXPECT_LT(allan_krobka_variance(phase, kTau0S, m), 1e-12 * expected) << m;
    // The ramp's second difference of rate is zero: Hadamard is blind to it already.
    EXPECT_LT(overlapping_hadamard_variance(phase, kTau0S, m), 1e-12 * expected) << m;
  }
}

TEST(AllanBatchKrobka, RampPlusWhiteNoiseLeavesTheWhiteLevel) {
  const double ramp_rad_s2 = 0.02, sigma_rad_s = 1.0;
  std::vector<double> rate = drifting_rate(100000, ramp_rad_s2, 0.0);
  add_white_rate_noise(rate, sigma_rad_s, 20240601);
  const std::vector<double> phase = phase_from_frequency(rate, kTau0S);
  for (int m : {10, 100, 1000}) {
    const double tau_s = m * kTau0S;
    const double white = sigma_rad_s * sigma_rad_s * kTau0S / tau_s;  // N^2 / tau
    const double ramp = ramp_rad_s2 * ramp_rad_s2 * tau_s * tau_s / 2.0;
    const double allan = std::sqrt(overlapping_allan_variance(phase, kTau0S, m));
    const double krobka = std::sqrt(allan_krobka_variance(phase, kTau0S, m));
    const DeviationBounds allan_bounds = white_fm_bounds(Statistic::kOverlappingAllan, allan, m, phase.size());
    const DeviationBounds krobka_bounds = white_fm_bounds(Statistic::kAllanKrobka, krobka, m, phase.size());
    // AVAR carries ramp + white; AKVAR only the white part, each within its 99 % interval.
    EXPECT_LE(allan_bounds.lower, std::sqrt(ramp + white)) << m;
    EXPECT_GE(allan_bounds.upper, std::sqrt(ramp + white)) << m;
    EXPECT_LE(krobka_bounds.lower, std::sqrt(white)) << m;
    EXPECT_GE(krobka_bounds.upper, std::sqrt(white)) << m;
  }
  // Where the ramp dominates, removing it changes the answer by more than the noise can.
  const double tau_s = 1000 * kTau0S;
  EXPECT_LT(allan_krobka_variance(phase, kTau0S, 1000), 0.1 * overlapping_allan_variance(phase, kTau0S, 1000))
      << "at tau = " << tau_s << " s";
}

TEST(AllanBatchKrobka, OnWhiteNoiseTheDispersionMatchesTheVariance) {
  std::vector<double> rate(100000, 0.0);
  add_white_rate_noise(rate, 0.5, 7);
  const std::vector<double> phase = phase_from_frequency(rate, kTau0S);
  for (int m : {1, 16, 256, 4096}) {
    for (auto [variance_statistic, dispersion_statistic] :
         {std::pair{Statistic::kOverlappingAllan, Statistic::kAllanKrobka},
          std::pair{Statistic::kOverlappingHadamard, Statistic::kHadamardKrobka}}) {
      const double parent = std::sqrt(variance(variance_statistic, phase, kTau0S, m));
      const double dispersion = std::sqrt(variance(dispersion_statistic, phase, kTau0S, m));
      const DeviationBounds parent_bounds = white_fm_bounds(variance_statistic, parent, m, phase.size());
      EXPECT_LE(dispersion, parent) << statistic_name(dispersion_statistic) << " m = " << m;
      EXPECT_GE(dispersion, parent_bounds.lower) << statistic_name(dispersion_statistic) << " m = " << m;
    }
  }
}

TEST(AllanBatchKrobka, HadamardKrobkaRemovesAQuadraticRateThatHadamardKeeps) {
  const double quadratic_rad_s3 = 1e-4, sigma_rad_s = 1.0;
  std::vector<double> rate = drifting_rate(100000, 0.0, quadratic_rad_s3);
  const std::vector<double> clean_phase = phase_from_frequency(rate, kTau0S);
  add_white_rate_noise(rate, sigma_rad_s, 99);
  const std::vector<double> noisy_phase = phase_from_frequency(rate, kTau0S);
  for (int m : {10, 100, 1000}) {
    const double tau_s = m * kTau0S;
    // y = c t^2 has a constant second difference of tau-averages, 2 c tau^2: HVAR = (2 c tau^2)^2 / 6.
    const double drift = std::pow(2.0 * quadratic_rad_s3 * tau_s * tau_s, 2) / 6.0;
    // Rounding of the ~1e4 rad cubic phase leaves ~1e-21 rad^2/s^2: compare well above it.
    if (m >= 100) {
      EXPECT_NEAR(overlapping_hadamard_variance(clean_phase, kTau0S, m) / drift, 1.0, 1e-6) << m;
      EXPECT_LT(hadamard_krobka_variance(clean_phase, kTau0S, m), 1e-9 * drift) << m;
    }
    const double white = sigma_rad_s * sigma_rad_s * kTau0S / tau_s;
    const double dispersion = std::sqrt(hadamard_krobka_variance(noisy_phase, kTau0S, m));
    const DeviationBounds bounds = white_fm_bounds(Statistic::kHadamardKrobka, dispersion, m, noisy_phase.size());
    EXPECT_LE(bounds.lower, std::sqrt(white)) << m;
    EXPECT_GE(bounds.upper, std::sqrt(white)) << m;
  }
}

TEST(AllanBatchKrobka, EdfIsTheParentsMinusOne) {
  for (int alpha : {2, 1, 0, -1, -2}) {
    for (int m : {1, 8, 64}) {
      EXPECT_DOUBLE_EQ(equivalent_degrees_of_freedom(Statistic::kAllanKrobka, alpha, m, 5000),
                       equivalent_degrees_of_freedom(Statistic::kOverlappingAllan, alpha, m, 5000) - 1.0);
      EXPECT_DOUBLE_EQ(equivalent_degrees_of_freedom(Statistic::kHadamardKrobka, alpha, m, 5000),
                       equivalent_degrees_of_freedom(Statistic::kOverlappingHadamard, alpha, m, 5000) - 1.0);
    }
  }
}

}  // namespace
}  // namespace allan
}  // namespace imu_lab
