#include "imu_lab/calib/kalibr_intrinsics.h"

#include <Eigen/QR>
#include <iomanip>
#include <sstream>

namespace imu_lab {
namespace calib {
void lower_triangular_times_rotation(const Eigen::Matrix3d& m, Eigen::Matrix3d& lower, Eigen::Matrix3d& rotation) {
  // M^T = Q R  =>  M = R^T Q^T; signs moved so that the diagonal is positive.
  const Eigen::HouseholderQR<Eigen::Matrix3d> qr(m.transpose());
  Eigen::Matrix3d q = qr.householderQ();
  Eigen::Matrix3d r = q.transpose() * m.transpose();
  const Eigen::Vector3d signs = r.diagonal().array().sign();
  q = q * signs.asDiagonal();
  r = signs.asDiagonal() * r;
  lower = r.transpose().triangularView<Eigen::Lower>();
  rotation = q.transpose();
}

KalibrIntrinsics kalibr_intrinsics(const ImuCalibration& calibration) {
  KalibrIntrinsics intrinsics;
  lower_triangular_times_rotation(calibration.accelerometer.scale_misalignment, intrinsics.Ta, intrinsics.body_to_imu);
  const Eigen::Matrix3d imu_to_body = intrinsics.body_to_imu.transpose();
  lower_triangular_times_rotation(calibration.gyro.scale_misalignment * imu_to_body, intrinsics.Tw,
                                  intrinsics.R_IMUtoGYRO);
  intrinsics.Tg = calibration.gyro.g_sensitivity * imu_to_body;
  return intrinsics;
}

std::string kalibr_imu_chain_yaml(const CalibrationResult& result, const std::string& topic, double rate_hz) {
  const KalibrIntrinsics k = kalibr_intrinsics(result.calibration);
  std::ostringstream out;
  out << std::setprecision(12);
  out << "%YAML:1.0\n"
      << "# Kalibr / OpenVINS IMU intrinsics from imu_lab fit_calibration (model \"kalibr\" =\n"
      << "# Kalibr's scale-misalignment): w_m = Tw R_IMUtoGYRO w + Tg a + b_g, a_m = Ta R_IMUtoACC a + b_a.\n"
      << "# The IMU frame is the accelerometer frame (R_IMUtoACC = I). Biases: gyro "
      << result.calibration.gyro.bias.transpose() << " rad/s, accelerometer "
      << result.calibration.accelerometer.bias.transpose() << " m/s^2 (OpenVINS estimates its own).\n"
      << "# Random walks are not measured by a calibration run: replace them with the allan tool's values.\n";
  identify::ImuChainNode node;
  node.accelerometer_noise_density = result.noise.force_density_m_s2_per_sqrt_hz.mean();
  node.gyroscope_noise_density = result.noise.rate_density_rad_s_per_sqrt_hz.mean();
  node.rostopic = topic;
  node.update_rate_hz = rate_hz;
  node.intrinsics = k;
  identify::write_imu_chain_node(out, node);
  return out.str();
}

}  // namespace calib
}  // namespace imu_lab
