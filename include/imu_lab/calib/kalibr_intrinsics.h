// The calibration in the IMU-intrinsics form of Kalibr's "scale-misalignment" model, as OpenVINS
// reads it from kalibr_imu_chain.yaml (model "kalibr"; ov_core's analytic propagation docs):
//   w_m = Tw * R_IMUtoGYRO * w_I + Tg * a_I + b_g,     a_m = Ta * R_IMUtoACC * a_I + b_a,
// with Tw and Ta lower triangular and R_IMUtoACC = I: the IMU frame I is the accelerometer frame.
// Mapping from ours (output = b + K * input + G f, in our body frame B):
//   K_a = Ta * Q (LQ decomposition, Ta lower triangular with a positive diagonal, Q a rotation
//   B -> I; Q = I in mode 2, where our frame already is the accelerometer frame);
//   K_g * Q^T = Tw * R_IMUtoGYRO (LQ again); Tg = G * Q^T; biases unchanged.
#pragma once

#include <Eigen/Core>
#include <string>

#include "imu_lab/calib/bench_calibration.h"
#include "imu_lab/identify/kalibr_yaml.h"

namespace imu_lab {
namespace calib {

struct KalibrIntrinsics : identify::KalibrImuIntrinsics {
  Eigen::Matrix3d body_to_imu = Eigen::Matrix3d::Identity();  // Q: our frame -> Kalibr's IMU frame
};

// M = L * Q with L lower triangular (positive diagonal) and Q a rotation.
void lower_triangular_times_rotation(const Eigen::Matrix3d& m, Eigen::Matrix3d& lower, Eigen::Matrix3d& rotation);

KalibrIntrinsics kalibr_intrinsics(const ImuCalibration& calibration);

// kalibr_imu_chain.yaml text for OpenVINS: imu0 with the noise densities (random walks are not
// measured by a calibration run: take them from the allan tool), rostopic, rate and the intrinsics.
std::string kalibr_imu_chain_yaml(const CalibrationResult& result, const std::string& topic, double rate_hz);

}  // namespace calib
}  // namespace imu_lab
