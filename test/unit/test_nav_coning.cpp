// Coning and sculling corrections on exact motions with analytic increments (body frame;
// reference frame inertial, so only the compensated increments and the attitude update are tested).
//
// Coning: q(t) = [cos(b/2), sin(b/2) cos(W t), sin(b/2) sin(W t), 0] (body -> inertial), whose
// body rate is w = (-W sin b sin W t, W sin b cos W t, -2 W sin^2(b/2)); the delta angle over
// [t0, t1] is (sin b [cos W t]_t0^t1, sin b [sin W t]_t0^t1, -2 W sin^2(b/2) (t1 - t0)).
// Sculling: roll angle a sin(W t) about x with specific force A sin(W t) along body y; over whole
// periods the inertial velocity is (0, 0, A J1(a) t) (the rectified "sculling" acceleration).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "imu_lab/nav/coning_sculling.h"
#include "imu_lab/nav/rotation.h"

namespace imu_lab {
namespace nav {
namespace {

constexpr double kDt_s = 0.01;
constexpr double kDuration_s = 10.0;
constexpr double kMotionRate_rad_s = 2.0 * M_PI * 2.0;  // 2 Hz, a whole number of periods in 10 s

struct ConingMotion {
  double half_angle_rad = 2.0 * M_PI / 180.0;
  Eigen::Quaterniond attitude(double t) const {
    const double s = std::sin(0.5 * half_angle_rad);
    return Eigen::Quaterniond(std::cos(0.5 * half_angle_rad), s * std::cos(kMotionRate_rad_s * t),
                              s * std::sin(kMotionRate_rad_s * t), 0.0);
  }
  Eigen::Vector3d deltaAngle(double t0, double t1) const {
    const double w = kMotionRate_rad_s, sin_b = std::sin(half_angle_rad);
    const double sin_half = std::sin(0.5 * half_angle_rad);
    return Eigen::Vector3d(sin_b * (std::cos(w * t1) - std::cos(w * t0)), sin_b * (std::sin(w * t1) - std::sin(w * t0)),
                           -2.0 * w * sin_half * sin_half * (t1 - t0));
  }
};

// Attitude error angle after kDuration_s of coning.
double coningAttitudeError_rad(bool coning_correction) {
  const ConingMotion motion;
  ConingScullingConfig config;
  config.coning_correction = coning_correction;
  ConingScullingCompensator compensator(config);
  Eigen::Quaterniond attitude = motion.attitude(0.0);
  const int steps = static_cast<int>(std::lround(kDuration_s / kDt_s));
  for (int k = 1; k <= steps; ++k) {
    ImuIncrement increment;
    increment.delta_angle_rad = motion.deltaAngle((k - 1) * kDt_s, k * kDt_s);
    increment.dt_s = kDt_s;
    attitude =
        propagate_attitude(attitude, compensator.compensate(increment).rotation_vector_rad, Eigen::Vector3d::Zero());
  }
  return rotation_vector_from_quaternion(attitude * motion.attitude(kDuration_s).conjugate()).norm();
}

// The error of a motion integrated with the correction off and on; on must be 10x smaller.
void expectCorrectionGainsTenfold(const std::function<double(bool)>& error_with_correction, const char* label,
                                  const char* unit) {
  const double uncorrected = error_with_correction(false);
  const double corrected = error_with_correction(true);
  std::printf("[nav] %s: error %.3e %s without, %.3e %s with correction (factor %.0f)\n", label, uncorrected, unit,
              corrected, unit, uncorrected / corrected);
  EXPECT_LT(corrected * 10.0, uncorrected);
}

TEST(NavConing, CorrectionReducesConingDriftTenfold) {
  EXPECT_GT(coningAttitudeError_rad(false), 1e-5);  // the motion really does cone
  expectCorrectionGainsTenfold(coningAttitudeError_rad, "coning 2 deg at 2 Hz, 100 Hz increments, 10 s, attitude",
                               "rad");
}

// Inertial velocity error after kDuration_s of sculling.
double scullingVelocityError_m_s(bool sculling_correction) {
  const double roll_amplitude_rad = 0.05, accel_amplitude_m_s2 = 5.0, w = kMotionRate_rad_s;
  ConingScullingConfig config;
  config.sculling_correction = sculling_correction;
  ConingScullingCompensator compensator(config);
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  const int steps = static_cast<int>(std::lround(kDuration_s / kDt_s));
  for (int k = 1; k <= steps; ++k) {
    const double t0 = (k - 1) * kDt_s, t1 = k * kDt_s;
    ImuIncrement increment;
    increment.delta_angle_rad = Eigen::Vector3d(roll_amplitude_rad * (std::sin(w * t1) - std::sin(w * t0)), 0, 0);
    increment.delta_velocity_m_s =
        Eigen::Vector3d(0, accel_amplitude_m_s2 * (std::cos(w * t0) - std::cos(w * t1)) / w, 0);
    increment.dt_s = kDt_s;
    const CompensatedIncrement compensated = compensator.compensate(increment);
    velocity += attitude * compensated.delta_velocity_m_s;
    attitude = propagate_attitude(attitude, compensated.rotation_vector_rad, Eigen::Vector3d::Zero());
  }
  const Eigen::Vector3d truth(0.0, 0.0,
                              accel_amplitude_m_s2 * std::cyl_bessel_j(1.0, roll_amplitude_rad) * kDuration_s);
  return (velocity - truth).norm();
}

TEST(NavSculling, CorrectionReducesScullingErrorTenfold) {
  expectCorrectionGainsTenfold(scullingVelocityError_m_s,
                               "sculling 0.05 rad / 5 m/s^2 at 2 Hz, 100 Hz increments, 10 s, velocity", "m/s");
}

}  // namespace
}  // namespace nav
}  // namespace imu_lab
