#include "imu_lab/calib/kalibr_intrinsics.h"

#include <Eigen/QR>
#include <iomanip>
#include <sstream>

namespace imu_lab {
namespace calib {
namespace {

void write_matrix(std::ostream& out, const std::string& key, const Eigen::Matrix3d& m) {
  out << "  " << key << ":\n";
  for (int row = 0; row < 3; ++row) {
    out << "    - [" << m(row, 0) << ", " << m(row, 1) << ", " << m(row, 2) << "]\n";
  }
}

}  // namespace

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
  out << "imu0:\n";
  out << "  T_i_b:\n    - [1.0, 0.0, 0.0, 0.0]\n    - [0.0, 1.0, 0.0, 0.0]\n    - [0.0, 0.0, 1.0, 0.0]\n"
      << "    - [0.0, 0.0, 0.0, 1.0]\n";
  out << "  accelerometer_noise_density: " << result.noise.force_density_m_s2_per_sqrt_hz.mean() << "\n";
  out << "  accelerometer_random_walk: 0.0\n";
  out << "  gyroscope_noise_density: " << result.noise.rate_density_rad_s_per_sqrt_hz.mean() << "\n";
  out << "  gyroscope_random_walk: 0.0\n";
  out << "  rostopic: " << topic << "\n  time_offset: 0.0\n  update_rate: " << rate_hz << "\n";
  out << "  model: \"kalibr\"\n";
  write_matrix(out, "Tw", k.Tw);
  write_matrix(out, "R_IMUtoGYRO", k.R_IMUtoGYRO);
  write_matrix(out, "Ta", k.Ta);
  write_matrix(out, "R_IMUtoACC", k.R_IMUtoACC);
  write_matrix(out, "Tg", k.Tg);
  return out.str();
}

}  // namespace calib
}  // namespace imu_lab
