// Rates that are the derivative of a stationary Gauss-Markov angle, generated exactly: the angle's
// state propagates with its closed-form transition and discrete noise covariance, and the
// interval average of the rate over [t, t + h] is exactly (angle(t + h) - angle(t)) / h
// (doc/noise_families.md). Both start stationary.
//  - ResonanceNoise: a damped second-order band-pass mode, state (z, z'), z'' + 2 zeta w_n z' +
//    w_n^2 z = white; transition Phi = e^{A h} of the underdamped oscillator and discrete noise
//    covariance P_inf - Phi P_inf Phi^T (P_inf = diag((rms / w_n)^2, rms^2)).
//  - HighPassWhiteNoise: white rate noise N through a first-order high-pass with corner f_c
//    (Krobka table 7.3, PSD N^2 f^2 / (f_c^2 + f^2)); the angle is first-order Markov with
//    decay 2 pi f_c and drive density N.
#pragma once

#include <Eigen/Core>

#include "imu_lab/noise/integrated_gauss_markov.h"
#include "imu_lab/noise/noise_process.h"
#include "imu_lab/noise/normal_stream.h"
#include "imu_lab/noise/process_parameters.h"

namespace imu_lab {
namespace noise {

class ResonanceNoise : public NoiseProcess {
 public:
  // Throws std::invalid_argument unless rms >= 0, f_n > 0 and 0 < width < 2 f_n.
  ResonanceNoise(const ResonanceParameters& parameters, NormalStream normals);
  double next_interval_average(double start_s, double interval_s) override;
  double allan_variance(double tau_s, double tau0_s) const override;
  double sample_variance(double interval_s) const override;
  std::string kind() const override { return "resonance"; }

  // The one-step transition and the lower Cholesky factor of the discrete noise covariance.
  const Eigen::Matrix2d& transition(double interval_s);
  const Eigen::Matrix2d& noise_factor(double interval_s);
  // z' at the end of the last interval (a point sample, not what the sensor reports).
  double angle_rate() const { return state_[1]; }

 private:
  void prepare(double interval_s);

  ResonanceParameters parameters_;
  NormalStream normals_;
  Eigen::Vector2d state_;  // angle z [v] and its rate z' [u]
  double prepared_interval_s_ = -1.0;
  Eigen::Matrix2d transition_ = Eigen::Matrix2d::Identity();
  Eigen::Matrix2d noise_factor_ = Eigen::Matrix2d::Zero();
};

class HighPassWhiteNoise : public NoiseProcess {
 public:
  // Throws std::invalid_argument unless density >= 0 and corner > 0.
  HighPassWhiteNoise(const HighPassWhiteParameters& parameters, NormalStream normals);
  double next_interval_average(double start_s, double interval_s) override;
  double allan_variance(double tau_s, double tau0_s) const override;
  double sample_variance(double interval_s) const override;
  std::string kind() const override { return "high_pass_white"; }

 private:
  HighPassWhiteParameters parameters_;
  IntegratedGaussMarkov angle_propagator_;
  NormalStream normals_;
  double angle_ = 0.0;
};

}  // namespace noise
}  // namespace imu_lab
