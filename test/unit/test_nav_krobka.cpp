// Krobka's non-commutative effect (Krobka 2015 eqs. 2.48, 3.7): white noise in angle,
// delta_omega = d zeta / dt with <zeta(t1) zeta(t2)> = Q' tau0'^2 delta(t1 - t2) per axis, leaves a
// non-rotating attitude bounded but makes a rotating one diffuse:
//   sigma^2(t) = 3 D t + 2 Q' tau0'^2 int_0^t |omega|^2 dt     (Krobka dispersion, 3 axes).
// First-order check: the inertial attitude error is S = sum_k B_k n_k with n_k = zeta_k -
// zeta_{k-1}; summing by parts, S = sum_k (B_k - B_{k+1}) zeta_k + boundary terms, and each term's
// trace variance is 2 (1 - cos |omega| dt) * 2 sigma_zeta^2 ~ 2 |omega|^2 dt^2 sigma_zeta^2.
// Discrete model: zeta_k is N(0, sigma_zeta^2) per axis, the sample average of the continuous
// white zeta, so Q' tau0'^2 = sigma_zeta^2 dt; white rate noise D adds N(0, D dt) per increment.
//
// Monte Carlo: the body spins at constant |omega| about an axis tumbling in the body, increments
// (100 ms) go through the coning compensator and attitude update; truth is the same run without
// noise. Slope of the dispersion between T/10 and T from M runs; its standard error comes from the
// spread of the per-run differences, and the runs are enough for a 20 % check to be > 4 sigma wide.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "imu_lab/nav/coning_sculling.h"
#include "imu_lab/nav/rotation.h"

namespace imu_lab {
namespace nav {
namespace {

constexpr double kDt_s = 0.1;
constexpr int kSteps = 3000;             // T = 300 s
constexpr int kEarlyStep = kSteps / 10;  // boundary terms are already in at T/10
constexpr int kRuns = 1000;
constexpr double kAngleNoiseSigma_rad = 1e-5;

struct NoiseCase {
  double rate_magnitude_rad_s;
  double angle_noise_sigma_rad;            // sigma_zeta per axis
  double rate_noise_intensity_rad2_per_s;  // D per axis

  double theorySlope_rad2_per_s() const {
    const double angle_noise_intensity = angle_noise_sigma_rad * angle_noise_sigma_rad * kDt_s;  // Q' tau0'^2
    return 3.0 * rate_noise_intensity_rad2_per_s +
           2.0 * angle_noise_intensity * rate_magnitude_rad_s * rate_magnitude_rad_s;
  }
};

struct SlopeEstimate {
  double slope_rad2_per_s;
  double standard_error_rad2_per_s;
  double dispersion_at_end_rad2;
};

// Body rate of constant magnitude whose axis tumbles: 60 deg off body z, turning at 0.3 rad/s.
Eigen::Vector3d tumblingRate(double magnitude_rad_s, double t) {
  const double tilt = M_PI / 3.0, tumble = 0.3 * t;
  return magnitude_rad_s *
         Eigen::Vector3d(std::sin(tilt) * std::cos(tumble), std::sin(tilt) * std::sin(tumble), std::cos(tilt));
}

SlopeEstimate measureDispersionSlope(const NoiseCase& noise, std::uint64_t seed) {
  std::vector<Eigen::Vector3d> delta_angles(kSteps);
  for (int k = 0; k < kSteps; ++k)
    delta_angles[k] = tumblingRate(noise.rate_magnitude_rad_s, (k + 0.5) * kDt_s) * kDt_s;

  const auto propagate = [&](const std::function<Eigen::Vector3d()>& angle_noise, Eigen::Quaterniond* early,
                             Eigen::Quaterniond* end) {
    ConingScullingCompensator compensator;
    Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();
    for (int k = 0; k < kSteps; ++k) {
      ImuIncrement increment;
      increment.delta_angle_rad = delta_angles[k] + angle_noise();
      increment.dt_s = kDt_s;
      attitude =
          propagate_attitude(attitude, compensator.compensate(increment).rotation_vector_rad, Eigen::Vector3d::Zero());
      if (k + 1 == kEarlyStep) *early = attitude;
    }
    *end = attitude;
  };
  Eigen::Quaterniond true_early, true_end;
  propagate([] { return Eigen::Vector3d::Zero().eval(); }, &true_early, &true_end);

  std::mt19937_64 generator(seed);
  std::normal_distribution<double> unit_normal(0.0, 1.0);
  const auto gaussian = [&](double sigma) {
    return Eigen::Vector3d(sigma * unit_normal(generator), sigma * unit_normal(generator),
                           sigma * unit_normal(generator));
  };
  const double rate_noise_sigma_rad = std::sqrt(noise.rate_noise_intensity_rad2_per_s * kDt_s);
  Eigen::Vector3d sum_early = Eigen::Vector3d::Zero(), sum_end = Eigen::Vector3d::Zero();
  double sum_difference = 0.0, sum_difference_squared = 0.0, sum_end_squared = 0.0;
  for (int run = 0; run < kRuns; ++run) {
    Eigen::Vector3d previous_zeta = gaussian(noise.angle_noise_sigma_rad);
    const auto angle_noise = [&] {
      const Eigen::Vector3d zeta = gaussian(noise.angle_noise_sigma_rad);
      const Eigen::Vector3d increment_noise = zeta - previous_zeta + gaussian(rate_noise_sigma_rad);
      previous_zeta = zeta;
      return increment_noise;
    };
    Eigen::Quaterniond early, end;
    propagate(angle_noise, &early, &end);
    const Eigen::Vector3d error_early = rotation_vector_from_quaternion(early * true_early.conjugate());
    const Eigen::Vector3d error_end = rotation_vector_from_quaternion(end * true_end.conjugate());
    sum_early += error_early;
    sum_end += error_end;
    const double difference = error_end.squaredNorm() - error_early.squaredNorm();
    sum_difference += difference;
    sum_difference_squared += difference * difference;
    sum_end_squared += error_end.squaredNorm();
  }
  const double mean_difference = sum_difference / kRuns;
  // Krobka dispersion: subtract the squared mean error vector (eq. 2.33).
  const double dispersion_growth =
      mean_difference - (sum_end / kRuns).squaredNorm() + (sum_early / kRuns).squaredNorm();
  const double difference_variance = (sum_difference_squared - kRuns * mean_difference * mean_difference) / (kRuns - 1);
  const double interval_s = (kSteps - kEarlyStep) * kDt_s;
  return {dispersion_growth / interval_s, std::sqrt(difference_variance / kRuns) / interval_s,
          sum_end_squared / kRuns - (sum_end / kRuns).squaredNorm()};
}

void expectSlopeMatchesTheory(const NoiseCase& noise, std::uint64_t seed, const char* label) {
  const SlopeEstimate estimate = measureDispersionSlope(noise, seed);
  const double theory = noise.theorySlope_rad2_per_s();
  std::printf(
      "[nav] Krobka %s: slope %.4e rad^2/s vs eq. 3.7 %.4e (ratio %.3f, %.1f standard errors off; "
      "standard error %.1f %%)\n",
      label, estimate.slope_rad2_per_s, theory, estimate.slope_rad2_per_s / theory,
      (estimate.slope_rad2_per_s - theory) / estimate.standard_error_rad2_per_s,
      100.0 * estimate.standard_error_rad2_per_s / theory);
  ASSERT_LT(4.0 * estimate.standard_error_rad2_per_s, 0.2 * theory) << "too few runs for a 20 % check";
  EXPECT_NEAR(estimate.slope_rad2_per_s, theory, 0.2 * theory);
}

TEST(NavKrobka, WhiteAngleNoiseDiffusesARotatingBodyAsEq37) {
  expectSlopeMatchesTheory({1.0, kAngleNoiseSigma_rad, 0.0}, 11, "|w| = 1 rad/s, angle noise only");
}

TEST(NavKrobka, WhiteRateNoiseAddsThreeDt) {
  const double rate_noise_intensity = 2e-11;  // ~ the angle-noise term, so both must be right
  expectSlopeMatchesTheory({1.0, kAngleNoiseSigma_rad, rate_noise_intensity}, 12, "|w| = 1 rad/s, angle + rate noise");
}

TEST(NavKrobka, NonRotatingBodyDoesNotDiffuse) {
  const NoiseCase still{0.0, kAngleNoiseSigma_rad, 0.0};
  const SlopeEstimate estimate = measureDispersionSlope(still, 13);
  const double rotating_theory = NoiseCase{1.0, kAngleNoiseSigma_rad, 0.0}.theorySlope_rad2_per_s();
  const double boundary_dispersion = 6.0 * kAngleNoiseSigma_rad * kAngleNoiseSigma_rad;  // |zeta_N - zeta_0|^2
  std::printf(
      "[nav] Krobka, not rotating: slope %.3e rad^2/s (%.3f of the rotating case), dispersion at "
      "T %.3e rad^2 vs bounded 6 sigma_zeta^2 = %.3e\n",
      estimate.slope_rad2_per_s, estimate.slope_rad2_per_s / rotating_theory, estimate.dispersion_at_end_rad2,
      boundary_dispersion);
  EXPECT_LT(std::abs(estimate.slope_rad2_per_s), 4.0 * estimate.standard_error_rad2_per_s);
  EXPECT_LT(std::abs(estimate.slope_rad2_per_s), 0.02 * rotating_theory);
  EXPECT_NEAR(estimate.dispersion_at_end_rad2, boundary_dispersion, 0.15 * boundary_dispersion);
}

}  // namespace
}  // namespace nav
}  // namespace imu_lab
