// The calibration model of an IMU, per triad (Golovach 2017 eqs. 3.29-3.37):
//   output = b + K * input (+ G * specific_force, gyro g-sensitivity) + noise,
// K a full 3x3 matrix (scale factors on the diagonal, misalignment and non-orthogonality off it).
// Correction: input = K^-1 (output - b - G * specific_force). The accelerometers are corrected
// first: the gyro's g-sensitivity needs the corrected specific force.
#pragma once

#include <Eigen/Core>

namespace imu_lab {
namespace calib {

struct TriadCalibration {
  Eigen::Vector3d bias = Eigen::Vector3d::Zero();                    // [rad/s] or [m/s^2]
  Eigen::Matrix3d scale_misalignment = Eigen::Matrix3d::Identity();  // K
  Eigen::Matrix3d g_sensitivity = Eigen::Matrix3d::Zero();           // gyro: [rad/s per m/s^2]

  // K^-1 (output - b - G * specific_force).
  Eigen::Vector3d correct(const Eigen::Vector3d& output,
                          const Eigen::Vector3d& specific_force_m_s2 = Eigen::Vector3d::Zero()) const;
  // (K_ii - 1) * 1e6.
  Eigen::Vector3d scale_factor_error_ppm() const;
  // Off-diagonal K_ij in arcsec (small angles; the diagonal is zero).
  Eigen::Matrix3d misalignment_arcsec() const;
};

struct CorrectedSample {
  Eigen::Vector3d angular_rate_rad_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_m_s2 = Eigen::Vector3d::Zero();
};

struct ImuCalibration {
  TriadCalibration gyro;
  TriadCalibration accelerometer;

  CorrectedSample correct(const Eigen::Vector3d& angular_rate_rad_s, const Eigen::Vector3d& specific_force_m_s2) const;
};

constexpr double kArcsecPerRad = 206264.80624709636;
constexpr double kDegPerRad = 57.295779513082323;

}  // namespace calib
}  // namespace imu_lab
