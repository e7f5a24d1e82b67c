// Unit conversions against hand values, the fit point selection, and the moment weights
// (checked through the covariance of ln N against a generalised least squares by hand).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <random>

#include "imu_lab/allan/streaming_tau_plan.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/identify/avar_covariance.h"
#include "imu_lab/identify/chi_squared.h"
#include "imu_lab/identify/fit_points.h"
#include "imu_lab/identify/fit_problem.h"
#include "imu_lab/identify/units.h"

namespace imu_lab {
namespace identify {
namespace {

constexpr double kPi = 3.14159265358979323846;

double scale_of(const std::vector<UnitScale>& units, const std::string& key) {
  for (const auto& unit : units) {
    if (unit.key == key) return unit.per_si;
  }
  ADD_FAILURE() << "no unit " << key;
  return 0.0;
}

TEST(IdentifyUnits, HandValues) {
  // 1 deg/sqrt(h) = pi/180/60 rad/sqrt(s) = 2.90888e-4 rad/s/sqrt(Hz).
  EXPECT_DOUBLE_EQ(units::kDegPerSqrtHour_rad_per_sqrt_s, kPi / 180.0 / 60.0);
  EXPECT_NEAR(units::kDegPerSqrtHour_rad_per_sqrt_s, 2.908882086657216e-4, 1e-18);
  EXPECT_NEAR(units::kDegPerHour_rad_s, 4.84813681109536e-6, 1e-19);
  EXPECT_NEAR(units::kDegPerHourPerSqrtHour_rad_s_per_sqrt_s, 4.84813681109536e-6 / 60.0, 1e-20);
  EXPECT_NEAR(units::kArcsecond_rad, 4.84813681109536e-6, 1e-19);
  EXPECT_DOUBLE_EQ(units::kMicroG_m_s2, 9.80665e-6);
  EXPECT_DOUBLE_EQ(units::kMeterPerSecondPerSqrtHour_m_s2_per_sqrt_hz, 1.0 / 60.0);

  const auto gyro_n = amplitude_units(SensorKind::kGyroscope, TermKind::kWhiteRate);
  EXPECT_NEAR(2.908882086657216e-4 * scale_of(gyro_n, "deg_per_sqrt_h"), 1.0, 1e-12);
  EXPECT_NEAR(kPi / 180.0 * scale_of(gyro_n, "deg_s_per_sqrt_hz"), 1.0, 1e-12);
  const auto gyro_b = amplitude_units(SensorKind::kGyroscope, TermKind::kBiasInstability);
  EXPECT_NEAR(4.84813681109536e-6 * scale_of(gyro_b, "deg_h"), 1.0, 1e-12);
  const auto gyro_k = amplitude_units(SensorKind::kGyroscope, TermKind::kRandomWalk);
  EXPECT_NEAR(4.84813681109536e-6 / 60.0 * scale_of(gyro_k, "deg_h_per_sqrt_h"), 1.0, 1e-12);
  const auto gyro_q = amplitude_units(SensorKind::kGyroscope, TermKind::kWhiteAngle);
  EXPECT_NEAR(4.84813681109536e-6 * scale_of(gyro_q, "arcsec"), 1.0, 1e-12);
  const auto gyro_r = amplitude_units(SensorKind::kGyroscope, TermKind::kRateRamp);
  EXPECT_NEAR(4.84813681109536e-6 / 3600.0 * scale_of(gyro_r, "deg_h_per_h"), 1.0, 1e-12);

  const auto accel_n = amplitude_units(SensorKind::kAccelerometer, TermKind::kWhiteRate);
  EXPECT_NEAR(scale_of(accel_n, "m_s_per_sqrt_h"), 60.0, 1e-12);  // 1 m/s^2/sqrt(Hz) = 60 m/s/sqrt(h)
  EXPECT_NEAR(9.80665e-6 * scale_of(accel_n, "micro_g_per_sqrt_hz"), 1.0, 1e-12);
  const auto accel_b = amplitude_units(SensorKind::kAccelerometer, TermKind::kBiasInstability);
  EXPECT_NEAR(9.80665e-6 * scale_of(accel_b, "micro_g"), 1.0, 1e-12);
  const auto accel_k = amplitude_units(SensorKind::kAccelerometer, TermKind::kRandomWalk);
  // 1 m/s^2/sqrt(s) = 3600 m/s/h * 60 /sqrt(h).
  EXPECT_NEAR(scale_of(accel_k, "m_s_per_h_per_sqrt_h"), 216000.0, 1e-9);
}

TEST(IdentifyLikelihood, ChiSquaredTailAndQuantile) {
  EXPECT_NEAR(chi_squared_quantile(0.999, 1.0), 10.827566, 1e-5);
  EXPECT_NEAR(chi_squared_upper_tail(3.841459, 1.0), 0.05, 1e-6);
}

// The law of ln(chi2_e / e): closed forms at e = 1 and 2 (digamma(1/2) = -gamma - 2 ln 2,
// trigamma(1/2) = pi^2 / 2, trigamma(1) = pi^2 / 6), the series beyond e = 200 against the special
// functions just below it, and 200000 draws at e = 3 (the sample variance's standard error there
// is 0.0033: the tolerance is 4 of them).
TEST(IdentifyLikelihood, TheLogOfAScaledChiSquaredHasDigammaMeanAndTrigammaVariance) {
  constexpr double kEulerGamma = 0.5772156649015329;
  EXPECT_NEAR(mean_log_scaled_chi_squared(1.0), -kEulerGamma - 2.0 * std::log(2.0) + std::log(2.0), 1e-12);
  EXPECT_NEAR(variance_log_scaled_chi_squared(1.0), kPi * kPi / 2.0, 1e-12);
  EXPECT_NEAR(mean_log_scaled_chi_squared(2.0), -kEulerGamma, 1e-12);
  EXPECT_NEAR(variance_log_scaled_chi_squared(2.0), kPi * kPi / 6.0, 1e-12);
  // Both fall like 1 / e there: e times each is continuous across e = 200.
  EXPECT_NEAR(200.0001 * variance_log_scaled_chi_squared(200.0001) / (199.9999 * variance_log_scaled_chi_squared(199.9999)),
              1.0, 1e-7);
  EXPECT_NEAR(200.0001 * mean_log_scaled_chi_squared(200.0001) / (199.9999 * mean_log_scaled_chi_squared(199.9999)),
              1.0, 1e-7);

  std::mt19937_64 generator(20261205);
  std::chi_squared_distribution<double> chi_squared(3.0);
  constexpr int kDraws = 200000;
  double sum = 0.0, sum_of_squares = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double log_ratio = std::log(chi_squared(generator) / 3.0);
    sum += log_ratio;
    sum_of_squares += log_ratio * log_ratio;
  }
  const double mean = sum / kDraws;
  const double variance = sum_of_squares / kDraws - mean * mean;
  EXPECT_NEAR(mean, mean_log_scaled_chi_squared(3.0), 4.0 * std::sqrt(variance / kDraws));
  EXPECT_NEAR(variance, variance_log_scaled_chi_squared(3.0), 4.0 * 0.0033);
  // The first order, 2 / e, is 30 % short of it at e = 3.
  EXPECT_GT(variance, 1.3 * 2.0 / 3.0);
}

std::vector<allan::StabilityPoint> curve(const std::vector<double>& taus) {
  std::vector<allan::StabilityPoint> points;
  for (double tau : taus) {
    allan::StabilityPoint p;
    p.tau_s = tau;
    p.averaging_factor = static_cast<int>(std::lround(tau));
    p.deviation = 1.0 / std::sqrt(tau);
    p.edf = 100.0 / tau;
    points.push_back(p);
  }
  return points;
}

// Off a decade grid (here hand-picked taus): points at least a factor 1.41 apart; an unusable
// point is skipped and the next one taken.
TEST(IdentifyFitPoints, KeepsPointsAFactorApartOffTheLadder) {
  auto points = curve({1, 1.5, 2, 5, 7, 8, 16, 40});
  points[3].deviation = 0.0;  // unusable (tau 5): tau 7 is kept instead
  const auto kept = select_fit_points(points);
  std::vector<double> taus;
  for (const FitPoint& point : kept) taus.push_back(point.tau_s);
  EXPECT_EQ(taus, (std::vector<double>{1, 1.5, 7, 16, 40}));
  EXPECT_DOUBLE_EQ(kept[1].avar, 1.0 / 1.5);
  EXPECT_THROW(select_fit_points(curve({1, 2})), InputError);
  EXPECT_THROW(select_fit_points(curve({1, 4, 2, 8})), InputError);
  EXPECT_EQ(octave_averaging_factors(10), (std::vector<int>{1, 2, 4}));
}

// On a decade grid the points are the ladder's, round(10^(k / 5)): 10 and 30 points per decade
// give the same set, so a denser grid cannot change the fit.
TEST(IdentifyFitPoints, DecadeGridsOfAnyDensityGiveTheLadder) {
  const auto grid = [](double per_decade) {
    std::vector<double> taus;
    for (int i = 0; std::pow(10.0, i / per_decade) < 2000.0; ++i) {
      const double m = static_cast<double>(std::llround(std::pow(10.0, i / per_decade)));
      if (taus.empty() || m != taus.back()) taus.push_back(m);
    }
    return taus;
  };
  const auto at_ten = select_fit_points(curve(grid(10.0)));
  const auto at_thirty = select_fit_points(curve(grid(30.0)));
  std::vector<int> ten, thirty;
  for (const FitPoint& point : at_ten) ten.push_back(point.averaging_factor);
  for (const FitPoint& point : at_thirty) thirty.push_back(point.averaging_factor);
  EXPECT_EQ(ten, (std::vector<int>{1, 2, 3, 4, 6, 10, 16, 25, 40, 63, 100, 158, 251, 398, 631, 1000, 1585}));
  EXPECT_EQ(thirty, ten);
}

// Beyond its exact range the streaming engine rounds each factor up to a multiple of the pyramid
// block (allan/streaming_tau_plan.h), so 1585 is reported as 1586 and 158489 as 158720: the
// ladder takes the nearest curve point, and 10 and 30 points per decade still give one set.
TEST(IdentifyFitPoints, EngineGridsBeyondTheExactRangeGiveTheSameLadder) {
  const auto engine_grid = [](double per_decade) {
    allan::StreamingOptions options;
    options.points_per_decade = per_decade;
    options.max_tau_s = 2000.0;
    std::vector<allan::StabilityPoint> points;
    for (const allan::PlannedLevel& level : allan::plan_taus(options, 0.01).levels) {
      for (int factor : level.level_averaging_factors) {
        allan::StabilityPoint point;
        point.averaging_factor = factor << level.level;
        point.tau_s = 0.01 * point.averaging_factor;
        point.deviation = 1.0 / std::sqrt(point.tau_s);
        points.push_back(point);
      }
    }
    return points;
  };
  const auto factors = [](const std::vector<FitPoint>& kept) {
    std::vector<int> m;
    for (const FitPoint& point : kept) m.push_back(point.averaging_factor);
    return m;
  };
  const std::vector<int> at_ten = factors(select_fit_points(engine_grid(10.0)));
  EXPECT_EQ(factors(select_fit_points(engine_grid(30.0))), at_ten);
  // round(10^(k / 5)) for k = 0 .. 26, the ten beyond 1000 as the engine reports them
  EXPECT_EQ(at_ten,
            (std::vector<int>{1,   2,    3,    4,    6,    10,   16,    25,    40,    63,    100,   158,    251,   398,
                              631, 1000, 1586, 2512, 3984, 6312, 10000, 15856, 25120, 39872, 63104, 100096, 158720}));
}

// The span of a record's points, as the fit forms it.
DataSpan span_of(const std::vector<FitPoint>& points, double tau0_s, long long samples) {
  DataSpan span;
  span.tau0_s = tau0_s;
  span.record_length_s = samples * tau0_s;
  span.sample_count = samples;
  span.tau_min_s = points.front().tau_s;
  span.tau_max_s = points.back().tau_s;
  span.smallest_avar = span.largest_avar = points.front().avar;
  for (const FitPoint& point : points) {
    span.smallest_avar = std::min(span.smallest_avar, point.avar);
    span.largest_avar = std::max(span.largest_avar, point.avar);
  }
  return span;
}

// For a white-noise-only model the GMM information about ln N is 4 (1' R^-1 1) with R the
// relative covariance of the AVAR estimates: sigma(ln N) = 1 / (2 sqrt(1' R^-1 1)). R here comes
// from the brute-force lag sum, independent of the weights' quadrature; dropping the correlation
// across taus (or the factor 2 of ln N in ln AVAR) breaks it.
TEST(IdentifyMoments, CovarianceOfLnNIsTheGeneralisedLeastSquaresOne) {
  const double tau0_s = 0.01, density = 2e-5;
  const long long samples = 20000;
  NoiseModel model;
  model.terms = {{TermKind::kWhiteRate, density, 0.0}};
  std::vector<FitPoint> points;
  for (int m : {1, 2, 4, 8, 16, 32, 64, 128}) {
    points.push_back({m * tau0_s, m, model_avar(model, m * tau0_s)});
  }
  ModelStructure structure;
  structure.slots = {{TermKind::kWhiteRate, false, 0.0}};
  const DataSpan span = span_of(points, tau0_s, samples);
  OavarCovariance covariance(averaging_factors(points), tau0_s, samples);
  const MomentWeights weights = moment_weights(points, model, covariance, 0.0);
  const SolveOutcome outcome = solve_model(points, structure, {std::log(1e-4)}, span, weights);
  ASSERT_TRUE(outcome.usable);
  // The moments are bias-corrected logarithms, so the noiseless curve returns N up to that
  // correction's second order (1e-4 relative at these EDFs).
  EXPECT_NEAR(std::exp(outcome.log_parameters[0]) / density, 1.0, 1e-3);
  const std::size_t n = points.size();
  Eigen::MatrixXd relative(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      relative(i, j) = oavar_covariance_by_direct_sum(model, points[i].averaging_factor, points[j].averaging_factor,
                                                      tau0_s, samples) /
                       (points[i].avar * points[j].avar);
    }
  }
  // Each log's variance is trigamma(e / 2) at the estimate's EDF e = 2 / relative variance; the
  // correlations are the AVARs'.
  Eigen::VectorXd log_scale(n);
  for (std::size_t i = 0; i < n; ++i) {
    log_scale(i) = std::sqrt(variance_log_scaled_chi_squared(2.0 / relative(i, i)) / relative(i, i));
  }
  relative = log_scale.asDiagonal() * relative * log_scale.asDiagonal();
  const double information = Eigen::VectorXd::Ones(n).dot(relative.ldlt().solve(Eigen::VectorXd::Ones(n)));
  const Eigen::MatrixXd log_covariance = log_parameter_covariance(points, structure, outcome.log_parameters, weights);
  EXPECT_NEAR(std::sqrt(log_covariance(0, 0)) * 2.0 * std::sqrt(information), 1.0, 1e-3);
}

// At the longest taus of a record an estimate has a few EDF, and the weights give its log the
// variance trigamma(e / 2) (1.6-2.5 times the first order's 2 / e there), plus the discrepancy's.
TEST(IdentifyMoments, TheWeightsGiveEachLogItsTrigammaVariance) {
  const double tau0_s = 0.01, density = 2e-5, discrepancy = 0.01;
  const long long samples = 20000;
  NoiseModel model;
  model.terms = {{TermKind::kWhiteRate, density, 0.0}};
  std::vector<FitPoint> points;
  for (int m : {1, 10, 100, 1000, 4000, 9000}) points.push_back({m * tau0_s, m, model_avar(model, m * tau0_s)});
  OavarCovariance covariance(averaging_factors(points), tau0_s, samples);
  const MomentWeights weights = moment_weights(points, model, covariance, discrepancy);
  const Eigen::MatrixXd log_covariance = (weights.whitening.transpose() * weights.whitening).inverse();
  ASSERT_LT(weights.edf(points.size() - 1), 3.0);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double first_order = 2.0 / weights.edf(k);
    EXPECT_NEAR(log_covariance(k, k), variance_log_scaled_chi_squared(weights.edf(k)) + discrepancy * discrepancy,
                1e-9 * log_covariance(k, k))
        << "at m = " << points[k].averaging_factor << " (EDF " << weights.edf(k) << ", first order " << first_order
        << ")";
    EXPECT_NEAR(weights.log_bias(k), mean_log_scaled_chi_squared(weights.edf(k)), 1e-12);
  }
}

// A profile's solve given a level stops at the first iterate under it; without one (or with a
// level under the minimum) it converges. The stopped iterate lies under the level and above the
// minimum, and a start already under the level is returned as it is.
TEST(IdentifyMoments, ASolveGivenALevelStopsAtTheFirstIterateUnderIt) {
  const double tau0_s = 0.01, density = 2e-5, rate_walk = 3e-4;
  const long long samples = 20000;
  NoiseModel model;
  model.terms = {{TermKind::kWhiteRate, density, 0.0}, {TermKind::kRandomWalk, rate_walk, 0.0}};
  std::vector<FitPoint> points;
  for (int m : {1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048}) {
    points.push_back({m * tau0_s, m, model_avar(model, m * tau0_s)});
  }
  ModelStructure structure;
  structure.slots = {{TermKind::kWhiteRate, false, 0.0}, {TermKind::kRandomWalk, false, 0.0}};
  const DataSpan span = span_of(points, tau0_s, samples);
  OavarCovariance covariance(averaging_factors(points), tau0_s, samples);
  const MomentWeights weights = moment_weights(points, model, covariance, 0.0);
  const std::vector<double> start = {std::log(30.0 * density), std::log(0.1 * rate_walk)};
  const double start_cost = model_cost(points, structure, start, weights);
  const SolveOutcome converged = solve_model(points, structure, start, span, weights);
  ASSERT_TRUE(converged.usable);
  ASSERT_LT(converged.cost, 1e-3 * start_cost);

  const double level = std::sqrt(start_cost * converged.cost);  // between, on a log scale
  const SolveOutcome stopped = solve_model(points, structure, start, span, weights, {}, level);
  ASSERT_TRUE(stopped.usable);
  EXPECT_LT(stopped.cost, level);
  EXPECT_GT(stopped.cost, converged.cost * (1.0 + 1e-6));
  EXPECT_NEAR(stopped.cost, model_cost(points, structure, stopped.log_parameters, weights), 1e-12 * start_cost);

  const SolveOutcome under_minimum = solve_model(points, structure, start, span, weights, {}, 0.5 * converged.cost);
  EXPECT_NEAR(under_minimum.cost, converged.cost, 1e-9 * start_cost);

  const SolveOutcome at_once = solve_model(points, structure, start, span, weights, {}, 2.0 * start_cost);
  EXPECT_EQ(at_once.log_parameters, start);
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
