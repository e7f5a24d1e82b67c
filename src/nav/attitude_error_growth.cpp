#include "imu_lab/nav/attitude_error_growth.h"

#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "imu_lab/noise/flicker_bank.h"

namespace imu_lab {
namespace nav {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
constexpr int kMaxTermStates = 2;
constexpr int kMaxJointStates = 3 + kMaxTermStates;

using TermMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxTermStates + 1, kMaxTermStates + 1>;
using JointMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxJointStates, kMaxJointStates>;

// One noise term of one axis as a linear model: s' = F s + G w (w unit white), rate error H s,
// s(0) ~ N(0, P0).
struct LinearTerm {
  std::string name;
  Eigen::MatrixXd F, G, H, P0;
};

LinearTerm scalar_term(const std::string& name, double decay_rate_per_s, double drive_density,
                       double initial_variance) {
  LinearTerm term{name, Eigen::MatrixXd::Constant(1, 1, -decay_rate_per_s),
                  Eigen::MatrixXd::Constant(1, 1, drive_density), Eigen::MatrixXd::Ones(1, 1),
                  Eigen::MatrixXd::Constant(1, 1, initial_variance)};
  return term;
}

// Stationary first-order Markov with the PSD (q_c T_c)^2 / (1 + (2 pi f T_c)^2).
LinearTerm markov_term(const std::string& name, double q_c_per_sqrt_s, double correlation_time_s) {
  return scalar_term(name, 1.0 / correlation_time_s, q_c_per_sqrt_s,
                     q_c_per_sqrt_s * q_c_per_sqrt_s * correlation_time_s / 2.0);
}

struct AxisTerms {
  double white_density_squared = 0.0;  // rad^2/s^2 per Hz
  double white_angle_sigma_rad = 0.0;  // per sample
  std::vector<LinearTerm> linear;
};

AxisTerms axis_terms(const GyroAxisErrors& gyro, int axis, double horizon_s) {
  const std::string where = "gyro axis " + std::to_string(axis) + ": ";
  AxisTerms terms;
  const double quantization = gyro.model.output_quantization_density;
  terms.white_density_squared = quantization * quantization;
  if (gyro.constant_bias_sigma_rad_s > 0.0) {
    terms.linear.push_back(scalar_term("constant_bias", 0.0, 0.0, std::pow(gyro.constant_bias_sigma_rad_s, 2)));
  }
  for (const identify::Term& term : gyro.model.terms) {
    const double a = term.amplitude;
    if (!(std::isfinite(a) && a >= 0.0) || !std::isfinite(term.shape) || !std::isfinite(term.width)) {
      throw std::invalid_argument(where + identify::term_kind_name(term.kind) + " has a non-finite or negative value");
    }
    switch (term.kind) {
      case identify::TermKind::kWhiteRate:
        if (term.shape > 0.0) {  // behind the front end's first-order low-pass (noise_model.h)
          const double correlation_time_s = 1.0 / (kTwoPi * term.shape);
          terms.linear.push_back(markov_term("white_rate", a / correlation_time_s, correlation_time_s));
        } else {
          terms.white_density_squared += a * a;
        }
        break;
      case identify::TermKind::kWhiteAngle:
        if (!(gyro.sample_interval_s > 0.0)) {
          throw std::invalid_argument(where + "a white-angle term needs the sample interval it refers to");
        }
        terms.white_angle_sigma_rad = std::hypot(terms.white_angle_sigma_rad, a);
        break;
      case identify::TermKind::kMarkov:
        if (!(term.shape > 0.0)) throw std::invalid_argument(where + "a Markov term needs T_c > 0");
        terms.linear.push_back(markov_term("markov", a / term.shape, term.shape));
        break;
      case identify::TermKind::kRandomWalk: terms.linear.push_back(scalar_term("random_walk", 0.0, a, 0.0)); break;
      case identify::TermKind::kBiasInstability: {
        if (!(term.shape > 0.0)) throw std::invalid_argument(where + "bias instability needs a cutoff f0 > 0");
        if (a == 0.0) break;
        noise::BiasInstabilityParameters parameters;
        parameters.coefficient = a;
        parameters.cutoff_frequency_hz = term.shape;
        parameters.tau_min_s = 1.0 / term.shape;
        parameters.tau_max_s = std::max(horizon_s, 10.0 / term.shape);
        const noise::FlickerBankDesign bank = noise::design_flicker_bank(parameters);
        for (std::size_t j = 0; j < bank.corner_frequencies_hz.size(); ++j) {
          terms.linear.push_back(
              markov_term("bias_instability", bank.drive_densities[j], 1.0 / (kTwoPi * bank.corner_frequencies_hz[j])));
        }
        break;
      }
      case identify::TermKind::kRateRamp: {  // R t, the slope a random constant of sigma R
        LinearTerm ramp{"rate_ramp", Eigen::MatrixXd::Zero(2, 2), Eigen::MatrixXd::Zero(2, 1),
                        Eigen::MatrixXd::Zero(1, 2), Eigen::MatrixXd::Zero(2, 2)};
        ramp.F(0, 1) = 1.0;
        ramp.H(0, 0) = 1.0;
        ramp.P0(1, 1) = a * a;
        terms.linear.push_back(ramp);
        break;
      }
      case identify::TermKind::kSinusoid: {  // Omega0 sin(2 pi f t + phase), the phase uniform
        const double w = kTwoPi * term.shape;
        LinearTerm sine{"sinusoid", Eigen::MatrixXd::Zero(2, 2), Eigen::MatrixXd::Zero(2, 1),
                        Eigen::MatrixXd::Zero(1, 2), Eigen::MatrixXd::Identity(2, 2) * (a * a / 2.0)};
        sine.F(0, 1) = w;
        sine.F(1, 0) = -w;
        sine.H(0, 0) = 1.0;
        terms.linear.push_back(sine);
        break;
      }
      case identify::TermKind::kResonance: {  // rate z' of z'' + 2 zeta w_n z' + w_n^2 z = white
        const double w_n = kTwoPi * term.shape;
        const double zeta = term.width / (2.0 * term.shape);
        if (!(w_n > 0.0) || !(zeta > 0.0) || !(zeta < 1.0)) {
          throw std::invalid_argument(where + "a resonance needs f_n > 0 and 0 < width < 2 f_n");
        }
        LinearTerm mode{"resonance", Eigen::MatrixXd::Zero(2, 2), Eigen::MatrixXd::Zero(2, 1),
                        Eigen::MatrixXd::Zero(1, 2), Eigen::MatrixXd::Zero(2, 2)};
        mode.F << 0.0, 1.0, -w_n * w_n, -2.0 * zeta * w_n;
        mode.G(1, 0) = std::sqrt(4.0 * zeta * w_n) * a;  // var z' = g^2 / (4 zeta w_n) = rms^2
        mode.H(0, 1) = 1.0;
        mode.P0(0, 0) = std::pow(a / w_n, 2);
        mode.P0(1, 1) = a * a;
        terms.linear.push_back(mode);
        break;
      }
      case identify::TermKind::kZeroDcFamily:
      case identify::TermKind::kZeroDcGaussian:
      case identify::TermKind::kHighPassWhite:
        throw std::invalid_argument(where + identify::term_kind_name(term.kind) +
                                    " is not modelled in the prediction (doc/attitude_error_budget.md)");
    }
  }
  return terms;
}

// Van Loan's discretisation of the term's state jointly with the integral of its rate over one
// step h: [s(h); integral] = [A; B] s(0) + e, cov e = Qd.
struct DiscreteTerm {
  TermMatrix A, B, Qd;  // m x m, 1 x m, (m+1) x (m+1)
  TermMatrix P0;
};

DiscreteTerm discretise(const LinearTerm& term, double h) {
  const int m = static_cast<int>(term.F.rows());
  const int n = m + 1;
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(n, n);
  F.topLeftCorner(m, m) = term.F;
  F.bottomLeftCorner(1, m) = term.H;
  Eigen::MatrixXd GGt = Eigen::MatrixXd::Zero(n, n);
  GGt.topLeftCorner(m, m) = term.G * term.G.transpose();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  M.topLeftCorner(n, n) = -F * h;
  M.topRightCorner(n, n) = GGt * h;
  M.bottomRightCorner(n, n) = F.transpose() * h;
  const Eigen::MatrixXd E = M.exp();
  const Eigen::MatrixXd Phi = E.bottomRightCorner(n, n).transpose();
  Eigen::MatrixXd Qd = Phi * E.topRightCorner(n, n);
  Qd = 0.5 * (Qd + Qd.transpose());
  DiscreteTerm d;
  d.A = Phi.topLeftCorner(m, m);
  d.B = Phi.bottomLeftCorner(1, m);
  d.Qd = Qd;
  d.P0 = term.P0;
  return d;
}

// Covariance of [psi (3); term states] for one term of one gyro axis.
struct JointCovariance {
  JointMatrix P;
};

Eigen::Matrix3d navigation_transition(const Eigen::Vector3d& rate_rad_s, double h) {
  const double angle = rate_rad_s.norm() * h;
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(-angle, rate_rad_s.normalized()).toRotationMatrix();
}

// One step of a linear term: psi' = Phi psi - c (B s + e2), s' = A s + e1.
void step_linear(JointMatrix& P, const DiscreteTerm& d, const Eigen::Matrix3d& Phi, const Eigen::Vector3d& c) {
  const int m = static_cast<int>(d.A.rows());
  JointMatrix T = JointMatrix::Zero(3 + m, 3 + m);
  T.topLeftCorner(3, 3) = Phi;
  T.topRightCorner(3, m) = -c * d.B;
  T.bottomRightCorner(m, m) = d.A;
  JointMatrix L = JointMatrix::Zero(3 + m, m + 1);
  L.topRightCorner(3, 1) = -c;
  L.bottomLeftCorner(m, m).setIdentity();
  P = T * P * T.transpose() + L * d.Qd * L.transpose();
}

// One step of the white angle term (state zeta, the angle error at the grid point):
// psi' = Phi psi + c_start zeta - c_end zeta' - sum over the step's inner samples.
void step_white_angle(JointMatrix& P, double sigma2, double samples_per_step, const Eigen::Matrix3d& Phi,
                      const Eigen::Vector3d& c_start, const Eigen::Vector3d& c_end) {
  JointMatrix T = JointMatrix::Zero(4, 4);
  T.topLeftCorner(3, 3) = Phi;
  T.topRightCorner(3, 1) = c_start;
  JointMatrix Q = JointMatrix::Zero(4, 4);
  Eigen::Matrix3d inner = Eigen::Matrix3d::Zero();
  if (samples_per_step > 1.0 + 1e-9) {
    const Eigen::Vector3d span = c_end - c_start;
    inner = span * span.transpose() / (samples_per_step - 1.0);
  }
  Q.topLeftCorner(3, 3) = sigma2 * (c_end * c_end.transpose() + inner);
  Q.topRightCorner(3, 1) = -sigma2 * c_end;
  Q.bottomLeftCorner(1, 3) = -sigma2 * c_end.transpose();
  Q(3, 3) = sigma2;
  P = T * P * T.transpose() + Q;
}

}  // namespace

std::vector<AttitudeSample> constant_rate_motion(const Eigen::Vector3d& body_rate_rad_s,
                                                 const Eigen::Quaterniond& start,
                                                 const Eigen::Vector3d& navigation_rate_rad_s, double duration_s,
                                                 double step_s) {
  if (!(step_s > 0.0) || !(duration_s >= step_s)) {
    throw std::invalid_argument("constant_rate_motion: need 0 < step <= duration");
  }
  const long long steps = std::llround(duration_s / step_s);
  std::vector<AttitudeSample> motion;
  motion.reserve(static_cast<std::size_t>(steps) + 1);
  const double rate = body_rate_rad_s.norm();
  for (long long k = 0; k <= steps; ++k) {
    const double t = k * step_s;
    AttitudeSample sample;
    sample.time_s = t;
    const Eigen::Quaterniond turn = rate > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(rate * t, body_rate_rad_s / rate))
                                               : Eigen::Quaterniond::Identity();
    sample.body_to_navigation = (start * turn).normalized();
    sample.navigation_rate_rad_s = navigation_rate_rad_s;
    motion.push_back(sample);
  }
  return motion;
}

std::vector<AttitudeErrorPoint> predict_attitude_error_growth(const std::array<GyroAxisErrors, 3>& gyros,
                                                              const std::vector<AttitudeSample>& motion,
                                                              int output_every) {
  if (motion.size() < 2) throw std::invalid_argument("attitude error growth: the motion needs at least 2 samples");
  if (output_every < 1) throw std::invalid_argument("attitude error growth: output_every must be >= 1");
  const double h = motion[1].time_s - motion[0].time_s;
  if (!(h > 0.0)) throw std::invalid_argument("attitude error growth: the motion's times must increase");
  for (std::size_t k = 1; k < motion.size(); ++k) {
    const double step = motion[k].time_s - motion[k - 1].time_s;
    if (!(std::abs(step - h) <= 1e-6 * h)) {
      throw std::invalid_argument("attitude error growth: the motion's grid is not uniform at sample " +
                                  std::to_string(k));
    }
  }
  const double horizon_s = motion.back().time_s - motion.front().time_s;

  // Per axis: its terms discretised once; per system (0 strapdown, 1 platform) their covariances.
  struct AxisState {
    AxisTerms terms;
    std::vector<DiscreteTerm> discrete;
    std::array<std::vector<JointMatrix>, 2> linear;
    std::array<JointMatrix, 2> white_angle;
    double samples_per_step = 1.0;
  };
  std::array<AxisState, 3> axes;
  for (int i = 0; i < 3; ++i) {
    AxisState& axis = axes[i];
    axis.terms = axis_terms(gyros[i], i, horizon_s);
    for (const LinearTerm& term : axis.terms.linear) {
      axis.discrete.push_back(discretise(term, h));
      const int m = static_cast<int>(term.F.rows());
      JointMatrix P = JointMatrix::Zero(3 + m, 3 + m);
      P.bottomRightCorner(m, m) = term.P0;
      for (auto& system : axis.linear) system.push_back(P);
    }
    if (axis.terms.white_angle_sigma_rad > 0.0) {
      axis.samples_per_step = h / gyros[i].sample_interval_s;
      if (axis.samples_per_step < 1.0 - 1e-9) {
        throw std::invalid_argument("attitude error growth: gyro axis " + std::to_string(i) +
                                    ": a white-angle term needs a step of at least its sample interval");
      }
    }
    for (auto& P : axis.white_angle) {
      P = JointMatrix::Zero(4, 4);
      P(3, 3) = std::pow(axis.terms.white_angle_sigma_rad, 2);
    }
  }

  std::vector<AttitudeErrorPoint> points;
  Eigen::Matrix3d white_sum[2] = {Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()};
  const auto record = [&](double time_s) {
    AttitudeErrorPoint point;
    point.time_s = time_s;
    Eigen::Matrix3d* totals[2] = {&point.strapdown_covariance_rad2, &point.platform_covariance_rad2};
    for (int system = 0; system < 2; ++system) {
      *totals[system] = white_sum[system];
      for (const AxisState& axis : axes) {
        for (const JointMatrix& P : axis.linear[system]) *totals[system] += P.topLeftCorner(3, 3);
        *totals[system] += axis.white_angle[system].topLeftCorner(3, 3);
      }
    }
    points.push_back(point);
  };
  record(motion.front().time_s);

  for (std::size_t k = 0; k + 1 < motion.size(); ++k) {
    const Eigen::Quaterniond& q0 = motion[k].body_to_navigation;
    const Eigen::Quaterniond& q1 = motion[k + 1].body_to_navigation;
    const Eigen::Matrix3d Phi =
        navigation_transition(0.5 * (motion[k].navigation_rate_rad_s + motion[k + 1].navigation_rate_rad_s), h);
    const Eigen::Matrix3d C_mid = q0.slerp(0.5, q1).toRotationMatrix();
    // White rate: its own covariance, carried by Phi like the rest.
    for (int system = 0; system < 2; ++system) {
      Eigen::Matrix3d added = Eigen::Matrix3d::Zero();
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d c = system == 0 ? Eigen::Vector3d(C_mid.col(i)) : Eigen::Vector3d::Unit(i);
        added += axes[i].terms.white_density_squared * h * c * c.transpose();
      }
      white_sum[system] = Phi * white_sum[system] * Phi.transpose() + added;
    }
    for (int i = 0; i < 3; ++i) {
      AxisState& axis = axes[i];
      for (int system = 0; system < 2; ++system) {
        const Eigen::Vector3d c = system == 0 ? Eigen::Vector3d(C_mid.col(i)) : Eigen::Vector3d::Unit(i);
        for (std::size_t j = 0; j < axis.discrete.size(); ++j)
          step_linear(axis.linear[system][j], axis.discrete[j], Phi, c);
        if (axis.terms.white_angle_sigma_rad > 0.0) {
          // The first and last samples of the step are mapped at their own mid-interval attitude.
          const double half_sample = 0.5 / axis.samples_per_step;
          const Eigen::Vector3d c_start = system == 0
                                              ? Eigen::Vector3d(q0.slerp(half_sample, q1).toRotationMatrix().col(i))
                                              : Eigen::Vector3d::Unit(i);
          const Eigen::Vector3d c_end = system == 0
                                            ? Eigen::Vector3d(q0.slerp(1.0 - half_sample, q1).toRotationMatrix().col(i))
                                            : Eigen::Vector3d::Unit(i);
          step_white_angle(axis.white_angle[system], std::pow(axis.terms.white_angle_sigma_rad, 2),
                           axis.samples_per_step, Phi, c_start, c_end);
        }
      }
    }
    if ((k + 1) % static_cast<std::size_t>(output_every) == 0 || k + 2 == motion.size()) record(motion[k + 1].time_s);
  }
  return points;
}

}  // namespace nav
}  // namespace imu_lab
