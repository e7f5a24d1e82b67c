// Static alignment on WGS-84 at 50 deg latitude with navigation-grade errors (gyro bias
// 0.003 deg/h, accelerometer bias 2e-5 g), against alignment_error_budget.h:
//  - biases only: errors equal the first-order prediction (residuals are second order, ~1e-9 rad);
//  - biases plus white noise: residuals are zero-mean with the derived covariance
//    (var tilt = N_a^2 / (g^2 T), var yaw = N_g^2 / (W^2 cos^2 L T) + tan^2 L var tilt); over 20
//    seeds the whitened residuals' chi-square (60 dof) must lie in its central 99.8 % interval and
//    every residual within 4.5 sigma.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "imu_lab/common/config_error.h"
#include "imu_lab/nav/alignment_error_budget.h"
#include "imu_lab/nav/static_alignment.h"
#include "test_nav_support.h"

namespace imu_lab {
namespace nav {
namespace {

using test_support::kDegPerHourToRadPerSecond;
using test_support::kDegToRad;

constexpr double kArcsecPerRad = 180.0 / M_PI * 3600.0;
constexpr double kStandardGravity = 9.80665;

struct AlignmentRun {
  double latitude_rad = 50.0 * kDegToRad;
  double height_m = 200.0;
  double dt_s = 0.1;
  Eigen::Quaterniond q_true = Eigen::Quaterniond(Eigen::AngleAxisd(30.0 * kDegToRad, Eigen::Vector3d::UnitZ()) *
                                                 Eigen::AngleAxisd(-3.0 * kDegToRad, Eigen::Vector3d::UnitY()) *
                                                 Eigen::AngleAxisd(2.0 * kDegToRad, Eigen::Vector3d::UnitX()));
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d(0.003, -0.003, 0.003) * kDegPerHourToRadPerSecond;
  Eigen::Vector3d accel_bias_m_s2 = Eigen::Vector3d(2e-5, -2e-5, 2e-5) * kStandardGravity;
  double gyro_arw_rad_per_sqrt_s = 0.0;
  double accel_vrw_m_s_per_sqrt_s = 0.0;
  StaticAlignmentConfig config;
};

const EarthModel& wgs84() {
  static const EarthModel earth{EarthModelConfig()};
  return earth;
}

Eigen::Vector3d alignmentError(const AlignmentRun& run, unsigned seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> unit_normal(0.0, 1.0);
  const auto noise = [&](double density) {
    const double sigma = density * std::sqrt(run.dt_s);  // white noise integrated over one sample
    return Eigen::Vector3d(sigma * unit_normal(generator), sigma * unit_normal(generator),
                           sigma * unit_normal(generator));
  };
  const ImuIncrement ideal =
      test_support::staticImuIncrement(wgs84(), run.q_true, run.latitude_rad, run.height_m, run.dt_s);
  StaticAligner aligner(run.config);
  while (!aligner.complete()) {
    ImuIncrement measured = ideal;
    measured.delta_angle_rad += run.gyro_bias_rad_s * run.dt_s + noise(run.gyro_arw_rad_per_sqrt_s);
    measured.delta_velocity_m_s += run.accel_bias_m_s2 * run.dt_s + noise(run.accel_vrw_m_s_per_sqrt_s);
    aligner.add(measured);
  }
  return test_support::attitudeError_rad(aligner.attitude(), run.q_true);
}

Eigen::Vector3d predictedError(const AlignmentRun& run) {
  return predicted_alignment_error_rad(run.gyro_bias_rad_s, run.accel_bias_m_s2, run.q_true, run.latitude_rad,
                                       wgs84().gravity_m_s2(run.latitude_rad, run.height_m),
                                       wgs84().earth_rate_rad_s());
}

TEST(NavAlignment, BiasesGiveThePredictedTiltAndHeadingErrors) {
  const AlignmentRun run;
  const Eigen::Vector3d measured = alignmentError(run, 0);
  const Eigen::Vector3d predicted = predictedError(run);
  std::printf(
      "[nav] alignment, biases only (arcsec, E N U): measured %.4f %.4f %.4f, predicted %.4f %.4f "
      "%.4f\n",
      measured.x() * kArcsecPerRad, measured.y() * kArcsecPerRad, measured.z() * kArcsecPerRad,
      predicted.x() * kArcsecPerRad, predicted.y() * kArcsecPerRad, predicted.z() * kArcsecPerRad);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(measured[axis], predicted[axis], 1e-3 * std::abs(predicted[axis])) << "axis " << axis;
  }
  EXPECT_GT(std::abs(predicted.z()), 1e-4);  // the heading term is not vacuous: ~1 arcmin
}

TEST(NavAlignment, NoiseStaysWithinTheDerivedBound) {
  AlignmentRun run;
  run.gyro_arw_rad_per_sqrt_s = 0.002 * kDegToRad / 60.0;   // 0.002 deg/sqrt(h)
  run.accel_vrw_m_s_per_sqrt_s = 20e-6 * kStandardGravity;  // 20 micro-g/sqrt(Hz)
  const Eigen::Matrix3d covariance = alignment_noise_covariance_rad2(
      run.gyro_arw_rad_per_sqrt_s, run.accel_vrw_m_s_per_sqrt_s, run.config.duration_s, run.latitude_rad,
      wgs84().gravity_m_s2(run.latitude_rad, run.height_m), wgs84().earth_rate_rad_s());
  const Eigen::Matrix3d whitening = covariance.llt().matrixL().solve(Eigen::Matrix3d::Identity());
  const Eigen::Vector3d sigma = covariance.diagonal().cwiseSqrt();
  const Eigen::Vector3d predicted = predictedError(run);
  constexpr int kSeeds = 20;
  double chi_square = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const Eigen::Vector3d residual = alignmentError(run, seed) - predicted;
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_LE(std::abs(residual[axis]), 4.5 * sigma[axis]) << "seed " << seed << " axis " << axis;
    }
    chi_square += (whitening * residual).squaredNorm();
  }
  std::printf(
      "[nav] alignment noise bound 1-sigma (arcsec, E N U): %.3f %.3f %.3f; chi-square %.1f for "
      "%d dof\n",
      sigma.x() * kArcsecPerRad, sigma.y() * kArcsecPerRad, sigma.z() * kArcsecPerRad, chi_square, 3 * kSeeds);
  EXPECT_GT(chi_square, 31.74);  // chi-square(60) 0.1 % quantile
  EXPECT_LT(chi_square, 99.61);  // 99.9 % quantile
}

TEST(NavAlignment, GivenHeadingLevelsAndKeepsTheGivenYaw) {
  AlignmentRun run;
  run.config.heading_source = HeadingSource::kGiven;
  const double yaw_error_rad = 0.01;
  run.config.given_yaw_rad = 30.0 * kDegToRad + yaw_error_rad;
  const Eigen::Vector3d measured = alignmentError(run, 0);
  const Eigen::Vector3d predicted = predictedError(run);
  EXPECT_NEAR(measured.x(), predicted.x(), 0.02 * std::abs(predicted.x()));
  EXPECT_NEAR(measured.y(), predicted.y(), 0.02 * std::abs(predicted.y()));
  // Levelling errors leak into the rotation about up only through sin(pitch) * roll error.
  EXPECT_NEAR(measured.z(), yaw_error_rad, 5e-6);
}

TEST(NavAlignment, RefusesToGyrocompassAtThePole) {
  AlignmentRun run;
  run.latitude_rad = 90.0 * kDegToRad;
  run.gyro_bias_rad_s.setZero();
  EXPECT_THROW(alignmentError(run, 0), InputError);
}

}  // namespace
}  // namespace nav
}  // namespace imu_lab
