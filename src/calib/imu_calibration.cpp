#include "imu_lab/calib/imu_calibration.h"

#include <Eigen/LU>

namespace imu_lab {
namespace calib {

Eigen::Vector3d TriadCalibration::correct(const Eigen::Vector3d& output,
                                          const Eigen::Vector3d& specific_force_m_s2) const {
  return scale_misalignment.partialPivLu().solve(output - bias - g_sensitivity * specific_force_m_s2);
}

Eigen::Vector3d TriadCalibration::scale_factor_error_ppm() const {
  return (scale_misalignment.diagonal().array() - 1.0) * 1e6;
}

Eigen::Matrix3d TriadCalibration::misalignment_arcsec() const {
  Eigen::Matrix3d angles = scale_misalignment * kArcsecPerRad;
  angles.diagonal().setZero();
  return angles;
}

CorrectedSample ImuCalibration::correct(const Eigen::Vector3d& angular_rate_rad_s,
                                        const Eigen::Vector3d& specific_force_m_s2) const {
  CorrectedSample corrected;
  corrected.specific_force_m_s2 = accelerometer.correct(specific_force_m_s2);
  corrected.angular_rate_rad_s = gyro.correct(angular_rate_rad_s, corrected.specific_force_m_s2);
  return corrected;
}

}  // namespace calib
}  // namespace imu_lab
