// The covariance of overlapping Allan variance estimates across taus (identify/avar_covariance.h):
// the lag sums against a brute-force sum over every lag, for every term kind, and the brute force
// itself against a Monte Carlo of simulated records (the structure functions are right).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "imu_lab/allan/batch.h"
#include "imu_lab/identify/avar_covariance.h"

namespace imu_lab {
namespace identify {
namespace {

constexpr double kTau0S = 0.01;

std::vector<double> phase_of(const std::vector<double>& rates) { return allan::phase_from_frequency(rates, kTau0S); }

std::vector<NoiseModel> models_of_every_kind() {
  std::vector<NoiseModel> models(4);
  models[0].terms = {{TermKind::kWhiteRate, 7e-4, 40.0}, {TermKind::kRandomWalk, 2e-6}, {TermKind::kMarkov, 1e-4, 0.5}};
  models[1].terms = {{TermKind::kWhiteRate, 7e-4, 0.0},
                     {TermKind::kBiasInstability, 1e-4, 50.0},
                     {TermKind::kWhiteAngle, 1e-5},
                     {TermKind::kRateRamp, 1e-7}};
  models[2].terms = {{TermKind::kWhiteRate, 7e-4, 30.0},
                     {TermKind::kResonance, 3e-3, 20.0, 1.5},
                     {TermKind::kZeroDcFamily, 1e-3, 0.5},
                     {TermKind::kSinusoid, 2e-4, 0.7}};
  models[3].terms = {{TermKind::kWhiteRate, 7e-4, 30.0}};
  models[3].output_quantization_density = 1e-4;
  return models;
}

// The lag sums use exact windows near the kinks of the structure functions and quadrature
// elsewhere; the brute force sums every lag. 2e-4 is ten times the largest difference seen.
TEST(IdentifyAvarCovariance, LagSumsMatchTheSumOverEveryLag) {
  const long long samples = 20000;
  const std::vector<std::pair<int, int>> pairs = {{1, 1},       {3, 5},       {10, 13},    {100, 200},
                                                  {1000, 1000}, {3000, 5000}, {9000, 9999}};
  for (const NoiseModel& model : models_of_every_kind()) {
    for (const auto& pair : pairs) {
      const double direct = oavar_covariance_by_direct_sum(model, pair.first, pair.second, kTau0S, samples);
      const Eigen::MatrixXd quadrature = oavar_covariance(model, {pair.first, pair.second}, kTau0S, samples);
      EXPECT_NEAR(quadrature(0, 1) / direct, 1.0, 2e-4)
          << "m " << pair.first << " n " << pair.second << " model of " << model.terms.size() << " terms";
      EXPECT_NEAR(quadrature(1, 0), quadrature(0, 1), 1e-12 * std::abs(direct));
    }
  }
}

// A curve pooled over segments holds a fraction of a contiguous record's terms: each variance
// grows by its inverse, the correlation stays; a fraction outside (0, 1] is refused.
TEST(IdentifyAvarCovariance, PooledTermFractionsInflateTheVariances) {
  NoiseModel model;
  model.terms = {{TermKind::kWhiteRate, 7e-4, 0.0}, {TermKind::kRandomWalk, 2e-6}};
  OavarCovariance contiguous({1, 10, 100}, kTau0S, 20000);
  OavarCovariance pooled({1, 10, 100}, kTau0S, 20000);
  pooled.set_pooled_term_fractions({1.0, 0.5, 0.25});
  const Eigen::MatrixXd c = contiguous.covariance(model);
  const Eigen::MatrixXd p = pooled.covariance(model);
  const std::vector<double> scale = {1.0, std::sqrt(2.0), 2.0};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(p(i, j), c(i, j) * scale[i] * scale[j], 1e-12 * std::abs(p(i, j)));
    EXPECT_NEAR(pooled.variance(model)[i], p(i, i), 1e-9 * p(i, i));
  }
  EXPECT_THROW(pooled.set_pooled_term_fractions({1.0, 0.0, 0.5}), std::invalid_argument);
  EXPECT_THROW(pooled.set_pooled_term_fractions({1.0, 0.5}), std::invalid_argument);
}

// Covariances of one record share their lag sums (every axis of a triad meets the same white,
// flicker and descriptive Markov terms). A sum shared must be the one a covariance alone would
// make: here the white and flicker kernels were first summed beside a slow Markov term, whose
// reach covers the whole record; the same terms alone are summed over their own reach, bit for
// bit as on a record of another factor set (which shares nothing; both sets' tables reach the
// same lags, so its first four rows are the same sums).
TEST(IdentifyAvarCovariance, SharedLagSumsAreThoseACovarianceAloneMakes) {
  const long long samples = 200000;
  const std::vector<int> factors = {1, 10, 100, 20000};
  NoiseModel with_slow_markov, without;
  without.terms = {{TermKind::kWhiteRate, 7e-4, 0.0}, {TermKind::kBiasInstability, 1e-4, 50.0}};
  with_slow_markov.terms = without.terms;
  with_slow_markov.terms.push_back({TermKind::kMarkov, 1e-4, 500.0});
  OavarCovariance first(factors, kTau0S, samples);
  first.covariance(with_slow_markov);
  OavarCovariance second(factors, kTau0S, samples);
  const Eigen::MatrixXd shared = second.covariance(without);
  std::vector<int> other_factors = factors;
  other_factors.push_back(30000);
  const Eigen::MatrixXd alone = oavar_covariance(without, other_factors, kTau0S, samples);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) EXPECT_EQ(shared(i, j), alone(i, j)) << "m " << factors[i] << " n " << factors[j];
  }
  const std::vector<double> variances = OavarCovariance(factors, kTau0S, samples).variance(without);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(variances[i], alone(i, i)) << "m " << factors[i];
}

// The sample covariance of the OAVAR estimates over many simulated records against the formula.
// Each entry's Monte Carlo standard error is about sqrt((1 + rho^2) / records) of the product of
// the two sigmas; 4.5 of them bound every entry with a family-wise false alarm rate near 1e-4.
// The lag sums are held to 2e-4 of the brute force unless a caller's form is an approximation.
template <class Record>
void expect_formula_matches_simulation(const NoiseModel& model, const std::vector<int>& factors, long long samples,
                                       int records, const Record& simulate_record, double quadrature_tolerance = 2e-4) {
  std::vector<std::vector<double>> estimates(factors.size());
  std::vector<double> rates(samples);
  for (int record = 0; record < records; ++record) {
    simulate_record(&rates);
    const std::vector<double> phase = phase_of(rates);
    for (std::size_t i = 0; i < factors.size(); ++i) {
      estimates[i].push_back(allan::overlapping_allan_variance(phase, kTau0S, factors[i]));
    }
  }
  Eigen::MatrixXd formula(factors.size(), factors.size());
  for (std::size_t i = 0; i < factors.size(); ++i) {
    for (std::size_t j = 0; j < factors.size(); ++j) {
      formula(i, j) = oavar_covariance_by_direct_sum(model, factors[i], factors[j], kTau0S, samples);
    }
  }
  const Eigen::MatrixXd quadrature = oavar_covariance(model, factors, kTau0S, samples);
  for (std::size_t i = 0; i < factors.size(); ++i) {
    for (std::size_t j = i; j < factors.size(); ++j) {
      double mean_i = 0.0, mean_j = 0.0;
      for (int r = 0; r < records; ++r) mean_i += estimates[i][r] / records, mean_j += estimates[j][r] / records;
      double sample = 0.0;
      for (int r = 0; r < records; ++r) sample += (estimates[i][r] - mean_i) * (estimates[j][r] - mean_j);
      sample /= records - 1;
      const double scale = std::sqrt(formula(i, i) * formula(j, j));
      const double rho = formula(i, j) / scale;
      const double standard_error = scale * std::sqrt((1.0 + rho * rho) / records);
      EXPECT_NEAR(sample, formula(i, j), 4.5 * standard_error) << "m " << factors[i] << " n " << factors[j];
      EXPECT_NEAR(quadrature(i, j), formula(i, j), quadrature_tolerance * scale)
          << "m " << factors[i] << " n " << factors[j];
    }
  }
}

// White rate noise plus a random walk.
TEST(IdentifyAvarCovariance, FormulaMatchesSimulatedRecords) {
  const double n_density = 1e-3, k_density = 3e-5;
  NoiseModel model;
  model.terms = {{TermKind::kWhiteRate, n_density, 0.0}, {TermKind::kRandomWalk, k_density}};
  std::mt19937_64 generator(20261201);
  std::normal_distribution<double> unit(0.0, 1.0);
  expect_formula_matches_simulation(model, {1, 4, 16, 64, 256}, 4000, 3000, [&](std::vector<double>* rates) {
    double walk = 0.0;
    for (double& rate : *rates) {
      walk += k_density * std::sqrt(kTau0S) * unit(generator);
      rate = n_density / std::sqrt(kTau0S) * unit(generator) + walk;
    }
  });
}

// White rate noise on a rate ramp that dominates the longest taus: the ramp adds no variance of
// its own, but its constant differences multiply the noise's mean difference (the cross term),
// which there is most of the estimates' variance.
TEST(IdentifyAvarCovariance, RampCrossTermMatchesSimulatedRecords) {
  const double n_density = 1e-3, ramp_per_s = 1e-4;
  NoiseModel model;
  model.terms = {{TermKind::kWhiteRate, n_density, 0.0}, {TermKind::kRateRamp, ramp_per_s}};
  std::mt19937_64 generator(20261202);
  std::normal_distribution<double> unit(0.0, 1.0);
  expect_formula_matches_simulation(model, {1, 16, 256, 1000, 1800}, 4000, 3000, [&](std::vector<double>* rates) {
    for (std::size_t k = 0; k < rates->size(); ++k) {
      (*rates)[k] = n_density / std::sqrt(kTau0S) * unit(generator) + ramp_per_s * (k + 0.5) * kTau0S;
    }
  });
}

// The ramp's cross term beside a random walk: a walk's record-long drift looks like a ramp, and
// the cross term must carry it (cov(mean d^m, mean d^n) of the walk's differences), where a
// ramp and a walk share the longest taus (as in the coverage bench's case 8, doc/identification.md).
TEST(IdentifyAvarCovariance, RampCrossTermBesideARandomWalkMatchesSimulatedRecords) {
  const double n_density = 1e-3, k_density = 3e-4, ramp_per_s = 1e-4;
  NoiseModel model;
  model.terms = {{TermKind::kWhiteRate, n_density, 0.0},
                 {TermKind::kRandomWalk, k_density},
                 {TermKind::kRateRamp, ramp_per_s}};
  std::mt19937_64 generator(20261204);
  std::normal_distribution<double> unit(0.0, 1.0);
  expect_formula_matches_simulation(model, {1, 16, 256, 1000, 1800}, 4000, 3000, [&](std::vector<double>* rates) {
    double walk = 0.0;
    for (std::size_t k = 0; k < rates->size(); ++k) {
      walk += k_density * std::sqrt(kTau0S) * unit(generator);
      (*rates)[k] = n_density / std::sqrt(kTau0S) * unit(generator) + walk + ramp_per_s * (k + 0.5) * kTau0S;
    }
  });
}

// White rate noise under a 3.3 Hz line of random phase that dominates the taus near its period
// (40 s, 132 periods): the line's differences multiply the noise's, and the cross term is most of
// the estimates' variance there. The simulation holds the phase-averaged brute force; the
// covariance's rank-one form (many periods) is held to it within 1 / (f T) of each entry's scale.
TEST(IdentifyAvarCovariance, SinusoidCrossTermMatchesSimulatedRecords) {
  const double n_density = 1e-3, line_peak = 2e-2, line_hz = 3.3;
  const long long samples = 4000;
  NoiseModel model;
  model.terms = {{TermKind::kWhiteRate, n_density, 0.0}, {TermKind::kSinusoid, line_peak, line_hz}};
  std::mt19937_64 generator(20261203);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * M_PI);
  const double angular = 2.0 * M_PI * line_hz;
  const std::vector<int> factors = {1, 4, 11, 30, 100, 400};
  // Without the cross term the formula falls short of the simulated variance by far at m = 11.
  NoiseModel noise_only;
  noise_only.terms = {model.terms[0]};
  EXPECT_GT(oavar_covariance_by_direct_sum(model, 11, 11, kTau0S, samples),
            20.0 * oavar_covariance_by_direct_sum(noise_only, 11, 11, kTau0S, samples));
  expect_formula_matches_simulation(
      model, factors, samples, 3000,
      [&](std::vector<double>* rates) {
        // Each sample is the line's exact mean over its interval, as an integrating sensor gives.
        const double phi = phase(generator);
        for (std::size_t k = 0; k < rates->size(); ++k) {
          const double line = line_peak / (angular * kTau0S) *
                              (std::cos(angular * k * kTau0S + phi) - std::cos(angular * (k + 1) * kTau0S + phi));
          (*rates)[k] = n_density / std::sqrt(kTau0S) * unit(generator) + line;
        }
      },
      1.0 / (line_hz * samples * kTau0S));
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
