// Ceres residuals of the bench calibration (private to src/calib). Parameter blocks, in order:
// accelerometer bias (3), accelerometer K (9, row-major), gyro bias (3), gyro K (9), gyro G (9),
// then the rotation-vector corrections of the rest attitudes involved (3 each):
// C_rest = C_nominal * Exp(delta), body -> ENU. In mode 1 the deltas are held constant at zero.
#pragma once

#include <ceres/rotation.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "imu_lab/calib/static_intervals.h"
#include "imu_lab/common/stamps.h"

namespace imu_lab {
namespace calib {
namespace residuals {

template <typename T>
using Vector3 = Eigen::Matrix<T, 3, 1>;
template <typename T>
using Matrix3 = Eigen::Matrix<T, 3, 3>;

template <typename T>
Matrix3<T> matrix_from_row_major(const T* elements) {
  Matrix3<T> matrix;
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) matrix(row, column) = elements[3 * row + column];
  }
  return matrix;
}

// Cofactor inverse: plain arithmetic, so it differentiates through Jets.
template <typename T>
Matrix3<T> inverse_of(const Matrix3<T>& m) {
  Matrix3<T> cofactors;
  cofactors(0, 0) = m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1);
  cofactors(0, 1) = m(1, 2) * m(2, 0) - m(1, 0) * m(2, 2);
  cofactors(0, 2) = m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0);
  cofactors(1, 0) = m(0, 2) * m(2, 1) - m(0, 1) * m(2, 2);
  cofactors(1, 1) = m(0, 0) * m(2, 2) - m(0, 2) * m(2, 0);
  cofactors(1, 2) = m(0, 1) * m(2, 0) - m(0, 0) * m(2, 1);
  cofactors(2, 0) = m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1);
  cofactors(2, 1) = m(0, 2) * m(1, 0) - m(0, 0) * m(1, 2);
  cofactors(2, 2) = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  const T determinant = m(0, 0) * cofactors(0, 0) + m(0, 1) * cofactors(0, 1) + m(0, 2) * cofactors(0, 2);
  return cofactors.transpose() / determinant;
}

// Quaternions as [w, x, y, z] arrays (ceres/rotation.h's order).
template <typename T>
std::array<T, 4> rest_attitude(const Eigen::Quaterniond& nominal, const T* delta) {
  const T nominal_wxyz[4] = {T(nominal.w()), T(nominal.x()), T(nominal.y()), T(nominal.z())};
  T correction[4];
  ceres::AngleAxisToQuaternion(delta, correction);
  std::array<T, 4> attitude;
  ceres::QuaternionProduct(nominal_wxyz, correction, attitude.data());
  return attitude;
}

template <typename T>
std::array<T, 4> conjugate(const std::array<T, 4>& q) {
  return {q[0], -q[1], -q[2], -q[3]};
}

template <typename T>
Vector3<T> rotate(const std::array<T, 4>& q, const Vector3<T>& v) {
  Vector3<T> result;
  ceres::UnitQuaternionRotatePoint(q.data(), v.data(), result.data());
  return result;
}

// A rest: mean force = b_a + K_a f_body, mean rate = b_g + K_g w_body + G f_body, with
// f_body = C^T (0, 0, g) and w_body = C^T (Earth rate in ENU).
struct RestResidual {
  Eigen::Quaterniond nominal_attitude;
  Eigen::Vector3d mean_force_m_s2, mean_rate_rad_s;
  Eigen::Vector3d force_sigma_m_s2, rate_sigma_rad_s;
  double gravity_m_s2 = 0.0;
  Eigen::Vector3d earth_rate_enu_rad_s;

  template <typename T>
  bool operator()(const T* accelerometer_bias, const T* accelerometer_k, const T* gyro_bias, const T* gyro_k,
                  const T* gyro_g_sensitivity, const T* delta, T* residual) const {
    const auto enu_to_body = conjugate(rest_attitude(nominal_attitude, delta));
    const Vector3<T> force_body = rotate(enu_to_body, Vector3<T>(T(0), T(0), T(gravity_m_s2)));
    const Vector3<T> rate_body = rotate(enu_to_body, Vector3<T>(earth_rate_enu_rad_s.cast<T>()));
    const Vector3<T> force_error = mean_force_m_s2.cast<T>() - Eigen::Map<const Vector3<T>>(accelerometer_bias) -
                                   matrix_from_row_major(accelerometer_k) * force_body;
    const Vector3<T> rate_error = mean_rate_rad_s.cast<T>() - Eigen::Map<const Vector3<T>>(gyro_bias) -
                                  matrix_from_row_major(gyro_k) * rate_body -
                                  matrix_from_row_major(gyro_g_sensitivity) * force_body;
    for (int axis = 0; axis < 3; ++axis) {
      residual[axis] = force_error[axis] / force_sigma_m_s2[axis];
      residual[3 + axis] = rate_error[axis] / rate_sigma_rad_s[axis];
    }
    return true;
  }
};

// A move between two rests: the corrected rates integrated over the samples in between must turn
// the first rest's attitude into the second's, with the Earth's own turn over that time:
//   R_known = C_from^T Exp(Earth rate_enu dt) C_to  (body at the end, in body axes at the start).
// Residual: the rotation vector of R_integrated^T R_known over its sigma per axis.
struct MoveResidual {
  const std::vector<io::ImuRecord>* samples = nullptr;
  std::size_t first = 0;  // samples [first, last) turn the body; their rates average over (t_k-1, t_k]
  std::size_t last = 0;
  Eigen::Quaterniond nominal_from, nominal_to;
  Eigen::Quaterniond earth_turn;  // Exp(Earth rate_enu * (t_last-1 - t_first-1))
  Eigen::Vector3d angle_sigma_rad;
  bool g_sensitivity = false;

  template <typename T>
  bool operator()(const T* accelerometer_bias, const T* accelerometer_k, const T* gyro_bias, const T* gyro_k,
                  const T* gyro_g_sensitivity, const T* delta_from, const T* delta_to, T* residual) const {
    const Matrix3<T> gyro_inverse = inverse_of(matrix_from_row_major(gyro_k));
    const Matrix3<T> accelerometer_inverse = inverse_of(matrix_from_row_major(accelerometer_k));
    const Matrix3<T> g_sensitivity_matrix = matrix_from_row_major(gyro_g_sensitivity);
    const Eigen::Map<const Vector3<T>> b_g(gyro_bias), b_a(accelerometer_bias);
    std::array<T, 4> integrated = {T(1), T(0), T(0), T(0)};
    for (std::size_t k = first; k < last; ++k) {
      const io::ImuRecord& sample = (*samples)[k];
      const double dt = seconds_between((*samples)[k - 1].stamp_ns, sample.stamp_ns);
      Vector3<T> rate = sample.angular_rate_rad_s.cast<T>() - b_g;
      if (g_sensitivity) {
        rate -= g_sensitivity_matrix * (accelerometer_inverse * (sample.specific_force_m_s2.cast<T>() - b_a));
      }
      const Vector3<T> angle = gyro_inverse * rate * T(dt);
      T step[4];
      ceres::AngleAxisToQuaternion(angle.data(), step);
      std::array<T, 4> next;
      ceres::QuaternionProduct(integrated.data(), step, next.data());
      integrated = next;
    }
    const T earth[4] = {T(earth_turn.w()), T(earth_turn.x()), T(earth_turn.y()), T(earth_turn.z())};
    const auto from = conjugate(rest_attitude(nominal_from, delta_from));
    const auto to = rest_attitude(nominal_to, delta_to);
    T from_earth[4], known[4], error[4];
    ceres::QuaternionProduct(from.data(), earth, from_earth);
    ceres::QuaternionProduct(from_earth, to.data(), known);
    ceres::QuaternionProduct(conjugate(integrated).data(), known, error);
    if (error[0] < T(0)) {
      for (T& component : error) component = -component;
    }
    T rotation_vector[3];
    ceres::QuaternionToAngleAxis(error, rotation_vector);
    for (int axis = 0; axis < 3; ++axis) residual[axis] = rotation_vector[axis] / angle_sigma_rad[axis];
    return true;
  }
};

// |g| cannot see a turn of every rest about the vertical; a weak prior holds the first rest's
// heading near its start value (Earth rate pins it properly when the gyros can sense it).
struct HeadingPrior {
  Eigen::Vector3d vertical_in_body;  // C_nominal^T (0, 0, 1)
  double sigma_rad = 1.0;

  template <typename T>
  bool operator()(const T* delta, T* residual) const {
    residual[0] =
        (T(vertical_in_body.x()) * delta[0] + T(vertical_in_body.y()) * delta[1] + T(vertical_in_body.z()) * delta[2]) /
        sigma_rad;
    return true;
  }
};

}  // namespace residuals
}  // namespace calib
}  // namespace imu_lab
