// kalibr_imu.yaml from the identified triads. Kalibr's convention (Kalibr wiki, "IMU Noise
// Model"): continuous-time densities, noise_density = N [u/sqrt(Hz)] (white-equivalent, see
// white_equivalent.h) and random_walk = K
// [u/s/sqrt(Hz)]; their discrete-time forms for a filter running at the update rate are
// N * sqrt(rate) [u] and K / sqrt(rate) [u/s... per step], written beside them under their own
// names. One number per sensor: the largest over its axes (conservative). A term the fit did not
// find, or could not constrain, contributes its upper bound and is flagged.
#pragma once

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

}  // namespace identify
}  // namespace imu_lab
