#include "imu_lab/calib/held_out_check.h"

#include <cmath>

#include "imu_lab/emulator/earth_model.h"

namespace imu_lab {
namespace calib {
namespace {

struct SpreadAccumulator {
  std::vector<double> raw, corrected;
  double expected_variance_sum = 0.0;

  InvariantSpread finish(double reference) const {
    InvariantSpread spread;
    spread.rests = raw.size();
    spread.reference = reference;
    spread.raw_spread = standard_deviation(raw);
    spread.corrected_spread = standard_deviation(corrected);
    spread.corrected_mean_error = mean(corrected) - reference;
    spread.expected_spread = raw.empty() ? 0.0 : std::sqrt(expected_variance_sum / raw.size());
    return spread;
  }
  static double mean(const std::vector<double>& values) {
    double sum = 0.0;
    for (double v : values) sum += v;
    return values.empty() ? 0.0 : sum / values.size();
  }
  static double standard_deviation(const std::vector<double>& values) {
    if (values.size() < 2) return 0.0;
    const double m = mean(values);
    double sum = 0.0;
    for (double v : values) sum += (v - m) * (v - m);
    return std::sqrt(sum / (values.size() - 1));
  }
};

// d|x|/d(parameters) for x = K^-1 (output - b - G f): row u^T K^-1 against b, K and G.
void add_gradient(ParameterVector& gradient, int bias_offset, int k_offset, int g_offset,
                  const Eigen::Matrix3d& k_inverse, const Eigen::Vector3d& corrected, const Eigen::Vector3d& force) {
  const Eigen::RowVector3d sensitivity = -(corrected.normalized().transpose() * k_inverse);
  for (int i = 0; i < 3; ++i) {
    gradient[bias_offset + i] = sensitivity[i];
    for (int j = 0; j < 3; ++j) {
      gradient[k_offset + 3 * i + j] = sensitivity[i] * corrected[j];
      if (g_offset >= 0) gradient[g_offset + 3 * i + j] = sensitivity[i] * force[j];
    }
  }
}

}  // namespace

HeldOutCheck held_out_check(const std::vector<RestMeans>& rests, const ImuCalibration& calibration,
                            const ParameterCovariance& covariance, const CalibrationSite& site) {
  using namespace parameter_offset;
  const Eigen::Matrix3d accelerometer_inverse = calibration.accelerometer.scale_misalignment.inverse();
  const Eigen::Matrix3d gyro_inverse = calibration.gyro.scale_misalignment.inverse();
  SpreadAccumulator gravity, earth_rate;
  for (const RestMeans& rest : rests) {
    const CorrectedSample corrected = calibration.correct(rest.mean_rate_rad_s, rest.mean_force_m_s2);
    const Eigen::Vector3d& force = corrected.specific_force_m_s2;
    const Eigen::Vector3d& rate = corrected.angular_rate_rad_s;
    gravity.raw.push_back(rest.mean_force_m_s2.norm());
    gravity.corrected.push_back(force.norm());
    earth_rate.raw.push_back(rest.mean_rate_rad_s.norm());
    earth_rate.corrected.push_back(rate.norm());

    ParameterVector gradient = ParameterVector::Zero();
    add_gradient(gradient, kAccelerometerBias, kAccelerometerK, -1, accelerometer_inverse, force, force);
    const Eigen::RowVector3d force_direction = (accelerometer_inverse.transpose() * force.normalized()).transpose();
    gravity.expected_variance_sum += (force_direction.cwiseAbs2() * rest.force_sigma_of_mean_m_s2.cwiseAbs2())(0) +
                                     gradient.dot(covariance * gradient);
    gradient.setZero();
    add_gradient(gradient, kGyroBias, kGyroK, kGyroGSensitivity, gyro_inverse, rate, force);
    const Eigen::RowVector3d rate_direction = (gyro_inverse.transpose() * rate.normalized()).transpose();
    earth_rate.expected_variance_sum += (rate_direction.cwiseAbs2() * rest.rate_sigma_of_mean_rad_s.cwiseAbs2())(0) +
                                        gradient.dot(covariance * gradient);
  }
  HeldOutCheck check;
  check.gravity_m_s2 = gravity.finish(site.gravity_m_s2());
  check.earth_rate_rad_s = earth_rate.finish(site.earth_rate_enu_rad_s().norm());
  return check;
}

}  // namespace calib
}  // namespace imu_lab
