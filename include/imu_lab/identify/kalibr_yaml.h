// kalibr_imu.yaml from the identified triads. Kalibr's convention (Kalibr wiki, "IMU Noise
// Model"): continuous-time densities, noise_density = N [u/sqrt(Hz)] (white-equivalent, see
// white_equivalent.h) and random_walk = K
// [u/s/sqrt(Hz)]; their discrete-time forms for a filter running at the update rate are
// N * sqrt(rate) [u] and K / sqrt(rate) [u/s... per step], written beside them under their own
// names. One number per sensor: the largest over its axes (conservative). A term the fit did not
// find, or could not constrain, contributes its upper bound and is flagged.
//
// kalibr_imu_chain.yaml: the same four numbers in the file OpenVINS reads (ov_msckf takes them
// key by key from its imu0 node, as in OpenVINS's config/*/kalibr_imu_chain.yaml), with the
// topic, the rate and the IMU model; an Allan run calibrates no intrinsics, so they are identity.
// Both files hold the recording's topic and say, in a comment, to set it to the user's own.
#pragma once

#include <Eigen/Core>
#include <ostream>
#include <string>

#include "imu_lab/identify/triad_fit.h"

namespace imu_lab {
namespace identify {

struct KalibrValue {
  double value = 0.0;           // continuous time, SI
  bool is_upper_bound = false;  // the fit found no constrained value; this is its bound
  int axis = 0;                 // the axis that gave it
};

struct KalibrImuNoise {
  KalibrValue gyroscope_noise_density;      // rad/s/sqrt(Hz)
  KalibrValue gyroscope_random_walk;        // rad/s^2/sqrt(Hz)
  KalibrValue accelerometer_noise_density;  // m/s^2/sqrt(Hz)
  KalibrValue accelerometer_random_walk;    // m/s^3/sqrt(Hz)
  double update_rate_hz = 0.0;              // measured
  std::string rostopic;
};

// The N (white_rate) or K (random_walk) entry of one triad: max over axes of the value, or of
// the upper bound for an axis where the term is absent or unconstrained.
KalibrValue kalibr_value(const TriadFit& triad, TermKind kind);

KalibrImuNoise kalibr_noise(const TriadFit& gyro, const TriadFit& accelerometer, double update_rate_hz,
                            const std::string& rostopic);

std::string format_kalibr_imu_yaml(const KalibrImuNoise& noise);
// Atomic (common/atomic_file.h).
void write_kalibr_imu_yaml(const std::string& path, const KalibrImuNoise& noise);

// Kalibr's scale-misalignment intrinsics (OpenVINS's "kalibr" model: w_m = Tw R_IMUtoGYRO w +
// Tg a + b_g, a_m = Ta R_IMUtoACC a + b_a); identity: none calibrated.
struct KalibrImuIntrinsics {
  Eigen::Matrix3d Tw = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d R_IMUtoGYRO = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d Ta = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d R_IMUtoACC = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d Tg = Eigen::Matrix3d::Zero();
};

// The imu0 node of OpenVINS's kalibr_imu_chain.yaml, shared by every writer of that file (this
// one and calib/kalibr_intrinsics.h's): the noise (continuous time, SI), topic, rate and the
// intrinsics.
struct ImuChainNode {
  double accelerometer_noise_density = 0.0;  // m/s^2/sqrt(Hz)
  double accelerometer_random_walk = 0.0;    // m/s^3/sqrt(Hz)
  double gyroscope_noise_density = 0.0;      // rad/s/sqrt(Hz)
  double gyroscope_random_walk = 0.0;        // rad/s^2/sqrt(Hz)
  std::string rostopic;
  std::string rostopic_comment;  // after the topic on its line; empty: none
  double update_rate_hz = 0.0;
  KalibrImuIntrinsics intrinsics;
};
// "imu0:" and its keys, in the stream's number format.
void write_imu_chain_node(std::ostream& out, const ImuChainNode& node);

// The whole kalibr_imu_chain.yaml of an Allan run: "%YAML:1.0" (OpenCV's FileStorage, which
// OpenVINS parses with, expects it), comments, then the node with identity intrinsics.
std::string format_kalibr_imu_chain_yaml(const KalibrImuNoise& noise);
// Atomic (common/atomic_file.h).
void write_kalibr_imu_chain_yaml(const std::string& path, const KalibrImuNoise& noise);

// The comment both files put on their rostopic line.
std::string rostopic_reminder(const std::string& rostopic);

}  // namespace identify
}  // namespace imu_lab
