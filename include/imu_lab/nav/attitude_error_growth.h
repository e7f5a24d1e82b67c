// Predicted growth of the attitude error (1-sigma per navigation axis, over time) that a gyro
// triad's noise causes in a strapdown system and in a platform (gimballed, stabilised) system with
// the same gyros, on a given angular motion [Krobka 2015, part 1; Titterton & Weston 2004, ch. 11].
//
// The error is the small rotation psi (navigation axes) with q_estimated = exp(psi) q_true, as in
// alignment_error_budget.h. With C(t) the body-to-navigation rotation, w_in the navigation frame's
// inertial rate (Earth rate plus transport rate) and d(t) the body-frame gyro error,
//   psi' = -w_in x psi - C(t) d(t)                 strapdown: the gyros turn with the body
//   psi' = -w_in x psi - d(t)                      platform: the gyros stay on navigation axes.
// The three axes' errors are independent, each a sum of independent terms; each term is a linear
// state-space model driven by white noise (doc/navigation.md, "Strapdown versus platform"):
//   white rate N (and the output quantization's white density): no state;
//   white rate behind a front-end low-pass, Markov (q_c T_c, T_c): first-order Markov, stationary;
//   bias instability B, f0: the emulator's bank of Markov processes (noise/flicker_bank.h) fitted
//     to eq. 5.3 of [Krobka 2015] over taus from 1 / f0 to the prediction's horizon;
//   random walk K: a random walk from zero;  constant (turn-on) bias: a random constant;
//   rate ramp R: R t with a random sign (slope sigma R); sinusoid: a random phase;
//   resonance: the damped second-order band-pass of noise/resonance_noise.h, stationary;
//   white angle Q (per-sample sigma at the sample period tau0): the increment carries
//     zeta_k - zeta_(k-1), so the error gets C_n zeta_n - C_1 zeta_0 - sum (C_(k+1) - C_k) zeta_k.
// Each term's states are propagated exactly over a step h (Van Loan's discretisation of the state
// jointly with its integral) together with psi, C held at the step's midpoint, and the terms'
// covariances of psi summed. Terms with no finite state-space model (the zero-DC families) are
// refused.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "imu_lab/identify/noise_model.h"

namespace imu_lab {
namespace nav {

// One gyro axis: its identified terms (noise.yaml) and what the Allan curve cannot see.
struct GyroAxisErrors {
  identify::NoiseModel model;
  double sample_interval_s = 0.0;          // tau0 the white angle's per-sample Q refers to
  double constant_bias_sigma_rad_s = 0.0;  // run-to-run (turn-on) bias, constant over a run
};

// The angular motion at one instant of a uniform time grid (the first at time 0).
struct AttitudeSample {
  double time_s = 0.0;
  Eigen::Quaterniond body_to_navigation = Eigen::Quaterniond::Identity();
  // Inertial rate of the navigation frame, in its axes (Earth rate plus transport rate).
  Eigen::Vector3d navigation_rate_rad_s = Eigen::Vector3d::Zero();
};

struct AttitudeErrorPoint {
  double time_s = 0.0;
  Eigen::Matrix3d strapdown_covariance_rad2 = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d platform_covariance_rad2 = Eigen::Matrix3d::Zero();
  Eigen::Vector3d strapdown_sigma_rad() const { return strapdown_covariance_rad2.diagonal().cwiseSqrt(); }
  Eigen::Vector3d platform_sigma_rad() const { return platform_covariance_rad2.diagonal().cwiseSqrt(); }
};

// The motion of a body turning at a constant body rate from attitude `start` under a navigation
// frame turning at a constant rate, sampled every step_s up to duration_s.
std::vector<AttitudeSample> constant_rate_motion(const Eigen::Vector3d& body_rate_rad_s,
                                                 const Eigen::Quaterniond& start,
                                                 const Eigen::Vector3d& navigation_rate_rad_s, double duration_s,
                                                 double step_s);

// The prediction at every `output_every`-th grid point of `motion` (and the last), the first at
// time 0 with zero covariance. Throws std::invalid_argument for fewer than 2 samples, a
// non-uniform grid, a step longer than a gyro's sample interval would allow (a white-angle term
// needs step >= tau0), output_every < 1, or a term with no state-space model here (naming it).
std::vector<AttitudeErrorPoint> predict_attitude_error_growth(const std::array<GyroAxisErrors, 3>& gyros,
                                                              const std::vector<AttitudeSample>& motion,
                                                              int output_every = 1);

}  // namespace nav
}  // namespace imu_lab
