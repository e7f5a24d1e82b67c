// Independent references for the scenario tests: composite Simpson and RK4 over known smooth
// segments, with the test's own Earth-frame formulas (radii, transport rate). Nothing here
// calls the emulator's kinematics; only the normal-gravity magnitude is shared (it has its own
// reference-value test).
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "imu_lab/emulator/earth_model.h"
#include "imu_lab/emulator/motion_source.h"
#include "imu_lab/emulator/scenario.h"
#include "test_emulator_paths.h"

namespace imu_lab {
namespace emulator {
namespace scenario_test {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

inline ScenarioConfig shipped_scenario(const std::string& file, EarthShape earth) {
  ScenarioConfig scenario = load_scenario(test::config_path("scenarios/" + file));
  scenario.earth_model = earth;
  return scenario;
}

// Rate of the ENU frame w.r.t. inertial space at the truth's position and velocity.
inline Eigen::Vector3d enu_frame_rate(const TruthState& truth, EarthShape earth) {
  const bool sphere = earth == EarthShape::kSphereNonRotating;
  const double e2 = sphere ? 0.0 : wgs84::kEccentricitySquared;
  const double a = sphere ? textbook_sphere::kRadius_m : wgs84::kSemiMajorAxis_m;
  const double s = std::sin(truth.latitude_rad);
  const double n = a / std::sqrt(1.0 - e2 * s * s);
  const double m = n * (1.0 - e2) / (1.0 - e2 * s * s);
  const Eigen::Vector3d& v = truth.velocity_enu_m_s;
  const double w = sphere ? 0.0 : wgs84::kEarthRate_rad_s;
  const Eigen::Vector3d earth_rate(0.0, w * std::cos(truth.latitude_rad), w * s);
  const Eigen::Vector3d transport(-v.y() / (m + truth.height_m), v.x() / (n + truth.height_m),
                                  v.x() * std::tan(truth.latitude_rad) / (n + truth.height_m));
  return earth_rate + transport;
}

// Splits [a, b] at the given instants; each piece's own end is evaluated just inside it, so a
// jump at a boundary is seen from the correct side.
inline std::vector<std::pair<double, double>> pieces(double a, double b, const std::vector<double>& cuts) {
  std::vector<std::pair<double, double>> result;
  double start = a;
  for (double cut : cuts) {
    if (cut > start && cut < b) {
      result.emplace_back(start, cut);
      start = cut;
    }
  }
  result.emplace_back(start, b);
  return result;
}

inline double inside(double t, double b, double a) { return t >= b ? std::nextafter(b, a) : t; }

// Composite Simpson of the truth's rate (first) and force (second) over [a, b].
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> simpson_increment(const MotionSource& motion, double a, double b,
                                                                     const std::vector<double>& cuts,
                                                                     int steps_per_piece) {
  Eigen::Vector3d rate = Eigen::Vector3d::Zero(), force = Eigen::Vector3d::Zero();
  for (const auto& [p0, p1] : pieces(a, b, cuts)) {
    const double h = (p1 - p0) / steps_per_piece;
    for (int i = 0; i <= steps_per_piece; ++i) {
      const double weight = (i == 0 || i == steps_per_piece) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      const TruthState truth = motion.truth_at(inside(p0 + i * h, p1, p0));
      rate += weight * h / 3.0 * truth.angular_rate_body_rad_s;
      force += weight * h / 3.0 * truth.specific_force_body_m_s2;
    }
  }
  return {rate, force};
}

struct NavigationState {
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  double latitude = 0.0, longitude = 0.0, height = 0.0;
};

struct IntegrationErrors {
  double attitude_rad = 0.0;
  double velocity_m_s = 0.0;
  double position_m = 0.0;
};

// RK4 of the strapdown equations driven by the truth's body rate and specific force:
//   q' = q (x) w_ib^b / 2 - w_in^n (x) q / 2,   v' = C f + g - (2 w_ie + w_en) x v,
//   lat' = v_N / (M + h), lon' = v_E / ((N + h) cos lat), h' = v_U,
// from the truth at 0, compared with the truth at every step; steps no longer than max_step_s,
// never across a cut.
inline IntegrationErrors integrate_against_truth(const MotionSource& motion, EarthShape earth, double end_s,
                                                 const std::vector<double>& cuts, double max_step_s) {
  const TruthState initial = motion.truth_at(0.0);
  NavigationState state{initial.attitude_body_to_enu, initial.velocity_enu_m_s, initial.latitude_rad,
                        initial.longitude_rad, initial.height_m};
  struct Derivative {
    Eigen::Vector4d attitude;
    Eigen::Vector3d velocity, position;
  };
  auto derivative = [&](const NavigationState& s, double t) {
    TruthState truth = motion.truth_at(t);
    TruthState here = truth;  // frame rate at the integrated position and velocity
    here.latitude_rad = s.latitude;
    here.height_m = s.height;
    here.velocity_enu_m_s = s.velocity;
    const Eigen::Vector3d frame_rate = enu_frame_rate(here, earth);
    const Eigen::Quaterniond body_rate(0.0, truth.angular_rate_body_rad_s.x(), truth.angular_rate_body_rad_s.y(),
                                       truth.angular_rate_body_rad_s.z());
    const Eigen::Quaterniond frame(0.0, frame_rate.x(), frame_rate.y(), frame_rate.z());
    const Eigen::Vector4d q_dot = 0.5 * ((s.attitude * body_rate).coeffs() - (frame * s.attitude).coeffs());
    const bool sphere = earth == EarthShape::kSphereNonRotating;
    here.velocity_enu_m_s.setZero();
    const Eigen::Vector3d earth_rate = enu_frame_rate(here, earth);
    const Eigen::Vector3d transport = frame_rate - earth_rate;
    const Eigen::Vector3d gravity(0.0, 0.0, -normal_gravity_m_s2(earth, s.latitude, s.height));
    const Eigen::Vector3d v_dot =
        s.attitude * truth.specific_force_body_m_s2 + gravity - (2.0 * earth_rate + transport).cross(s.velocity);
    const double e2 = sphere ? 0.0 : wgs84::kEccentricitySquared;
    const double a = sphere ? textbook_sphere::kRadius_m : wgs84::kSemiMajorAxis_m;
    const double sl = std::sin(s.latitude);
    const double n = a / std::sqrt(1.0 - e2 * sl * sl);
    const double m = n * (1.0 - e2) / (1.0 - e2 * sl * sl);
    const Eigen::Vector3d p_dot(s.velocity.y() / (m + s.height),
                                s.velocity.x() / ((n + s.height) * std::cos(s.latitude)), s.velocity.z());
    return Derivative{q_dot, v_dot, p_dot};
  };
  auto advance = [](const NavigationState& s, const Derivative& d, double h) {
    NavigationState next = s;
    next.attitude.coeffs() += h * d.attitude;
    next.velocity += h * d.velocity;
    next.latitude += h * d.position.x();
    next.longitude += h * d.position.y();
    next.height += h * d.position.z();
    return next;
  };
  IntegrationErrors worst;
  for (const auto& [p0, p1] : pieces(0.0, end_s, cuts)) {
    const int steps = static_cast<int>(std::ceil((p1 - p0) / max_step_s));
    const double h = (p1 - p0) / steps;
    for (int i = 0; i < steps; ++i) {
      const double t = p0 + i * h;
      const double t_mid = t + 0.5 * h, t_end = inside(t + h, p1, p0);
      const Derivative k1 = derivative(state, t);
      const Derivative k2 = derivative(advance(state, k1, 0.5 * h), t_mid);
      const Derivative k3 = derivative(advance(state, k2, 0.5 * h), t_mid);
      const Derivative k4 = derivative(advance(state, k3, h), t_end);
      Derivative sum{(k1.attitude + 2 * k2.attitude + 2 * k3.attitude + k4.attitude) / 6.0,
                     (k1.velocity + 2 * k2.velocity + 2 * k3.velocity + k4.velocity) / 6.0,
                     (k1.position + 2 * k2.position + 2 * k3.position + k4.position) / 6.0};
      state = advance(state, sum, h);
      state.attitude.normalize();
      const TruthState truth = motion.truth_at(t_end);
      const double radius = textbook_sphere::kRadius_m;
      worst.attitude_rad = std::max(worst.attitude_rad, state.attitude.angularDistance(truth.attitude_body_to_enu));
      worst.velocity_m_s = std::max(worst.velocity_m_s, (state.velocity - truth.velocity_enu_m_s).norm());
      worst.position_m = std::max(worst.position_m, radius * std::hypot(state.latitude - truth.latitude_rad,
                                                                        (state.longitude - truth.longitude_rad) *
                                                                            std::cos(truth.latitude_rad)) +
                                                        std::abs(state.height - truth.height_m));
    }
  }
  return worst;
}

}  // namespace scenario_test
}  // namespace emulator
}  // namespace imu_lab
