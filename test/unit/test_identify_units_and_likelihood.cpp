// Unit conversions against hand values, the chi-squared deviance, octave point selection, and
// the EDF weighting of the likelihood (checked through the Ceres covariance).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "imu_lab/common/config_error.h"
#include "imu_lab/identify/avar_likelihood.h"
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

TEST(IdentifyLikelihood, DevianceIsZeroAtTheMeasurementAndMatchesItsDerivative) {
  EXPECT_DOUBLE_EQ(point_deviance(2.0, 2.0, 50.0), 0.0);
  EXPECT_NEAR(point_deviance(3.0, 2.0, 10.0), 10.0 * (1.5 - 1.0 - std::log(1.5)), 1e-12);
  for (double model : {0.5, 0.99, 0.9999999, 1.0, 1.0000001, 1.3, 4.0}) {
    const DevianceResidual r = deviance_residual(1.0, model, 20.0);
    EXPECT_NEAR(r.value * r.value, point_deviance(1.0, model, 20.0), 1e-12);
    const double h = 1e-6;
    const double numeric = (deviance_residual(1.0, model * std::exp(h), 20.0).value -
                            deviance_residual(1.0, model * std::exp(-h), 20.0).value) / (2 * h);
    EXPECT_NEAR(r.derivative_wrt_log_model, numeric, 1e-5 * std::max(1.0, std::abs(numeric)))
        << "model " << model;
  }
  EXPECT_NEAR(deviance_residual(1.0, 1.0, 8.0).derivative_wrt_log_model, -2.0, 1e-12);  // -sqrt(edf/2)
}

TEST(IdentifyLikelihood, ChiSquaredTailAndQuantile) {
  EXPECT_NEAR(chi_squared_quantile(0.999, 1.0), 10.827566, 1e-5);
  EXPECT_NEAR(chi_squared_upper_tail(3.841459, 1.0), 0.05, 1e-6);
}

std::vector<allan::StabilityPoint> curve(const std::vector<double>& taus) {
  std::vector<allan::StabilityPoint> points;
  for (double tau : taus) {
    allan::StabilityPoint p;
    p.tau_s = tau;
    p.deviation = 1.0 / std::sqrt(tau);
    p.edf = 100.0 / tau;
    points.push_back(p);
  }
  return points;
}

TEST(IdentifyFitPoints, KeepsOneUsablePointPerOctave) {
  auto points = curve({1, 1.5, 2, 3, 4, 5, 8, 16});
  points[6].edf = 0.0;  // unusable: skipped, the next octave point is taken instead
  const auto kept = select_octave_points(points);
  ASSERT_EQ(kept.size(), 4u);
  EXPECT_EQ(kept[0].tau_s, 1.0);
  EXPECT_EQ(kept[1].tau_s, 2.0);
  EXPECT_EQ(kept[2].tau_s, 4.0);
  EXPECT_EQ(kept[3].tau_s, 16.0);
  EXPECT_DOUBLE_EQ(kept[1].avar, 0.5);
  auto rising = curve({1, 2, 4});
  rising[1].edf = 1000.0;  // a failed noise-type estimate
  EXPECT_DOUBLE_EQ(select_octave_points(rising)[1].edf, 100.0);
  EXPECT_THROW(select_octave_points(curve({1, 2})), InputError);
  EXPECT_THROW(select_octave_points(curve({1, 4, 2, 8})), InputError);
  EXPECT_EQ(octave_averaging_factors(10), (std::vector<int>{1, 2, 4}));
}

// For a white-noise-only model the information about ln N is sum(edf_k / 2 * 2^2): the Ceres
// covariance must give sigma(ln N) = 1 / sqrt(2 sum edf). Dropping the EDF weighting breaks it.
TEST(IdentifyLikelihood, CovarianceCarriesEachPointsEdf) {
  std::vector<FitPoint> points;
  double edf_sum = 0.0;
  for (int k = 0; k < 8; ++k) {
    const double tau = std::pow(2.0, k);
    const double edf = 3000.0 / (1.0 + k * k);
    points.push_back({tau, 4e-10 / tau, edf});
    edf_sum += edf;
  }
  ModelStructure structure;
  structure.slots = {{TermKind::kWhiteRate, false, 0.0}};
  const DataSpan span{0.5, 1000.0, 1.0, 128.0};
  SolverSettings settings;
  const SolveOutcome outcome = solve_model(points, structure, {std::log(1e-4)}, span, settings);
  ASSERT_TRUE(outcome.usable);
  EXPECT_NEAR(std::exp(outcome.log_parameters[0]), 2e-5, 1e-11);
  Eigen::MatrixXd covariance;
  ASSERT_TRUE(log_parameter_covariance(points, structure, outcome.log_parameters, settings,
                                       &covariance));
  EXPECT_NEAR(std::sqrt(covariance(0, 0)), 1.0 / std::sqrt(2.0 * edf_sum), 1e-6);
}

}  // namespace
}  // namespace identify
}  // namespace imu_lab
