#include "imu_lab/nav/navigator.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/format_number.h"
#include "imu_lab/nav/rotation.h"

namespace imu_lab {
namespace nav {

namespace {

double wrap_longitude(double longitude_rad) { return std::remainder(longitude_rad, 2.0 * M_PI); }

}  // namespace

std::string state_problem(const NavState& state) {
  const bool finite = std::isfinite(state.stamp_s) && state.q_body_to_enu.coeffs().allFinite() &&
                      state.velocity_enu_m_s.allFinite() && std::isfinite(state.latitude_rad) &&
                      std::isfinite(state.longitude_rad) && std::isfinite(state.height_m);
  if (!finite) return "NaN or Inf in the state";
  if (!(state.q_body_to_enu.norm() > 0.5)) return "the attitude quaternion is zero";
  if (!(std::abs(state.latitude_rad) < 0.5 * M_PI)) {
    return "latitude_rad = " + std::to_string(state.latitude_rad) +
           " is not strictly between -pi/2 and pi/2 (radians, not degrees?); the ENU mechanisation is singular at "
           "the poles";
  }
  if (!(std::abs(state.height_m) <= kMaxAbsoluteHeight_m)) {
    return "height " + format_number(state.height_m, 4) + " m is beyond +-" +
           format_number(kMaxAbsoluteHeight_m / 1e3, 4) + " km";
  }
  return "";
}

Navigator::Navigator(const NavigatorConfig& config)
    : earth_(config.earth), vertical_(config.vertical), compensator_(config.corrections) {}

void Navigator::initialise(const NavState& initial_state) {
  const std::string problem = state_problem(initial_state);
  if (!problem.empty()) {
    throw InputError("nav: initial state: " + problem + "; check the alignment or the initial-state parameters");
  }
  state_ = initial_state;
  state_.q_body_to_enu.normalize();
  state_.longitude_rad = wrap_longitude(state_.longitude_rad);
  compensator_.reset();
  initialised_ = true;
}

const NavState& Navigator::update(const Eigen::Vector3d& delta_angle_rad, const Eigen::Vector3d& delta_velocity_m_s,
                                  double dt_s) {
  ImuIncrement increment;
  increment.delta_angle_rad = delta_angle_rad;
  increment.delta_velocity_m_s = delta_velocity_m_s;
  increment.dt_s = dt_s;
  return update(increment);
}

const NavState& Navigator::update(const ImuIncrement& increment) {
  if (!initialised_) throw std::logic_error("nav: Navigator::update called before initialise");
  validate_increment(increment);
  const double dt = increment.dt_s;
  const CompensatedIncrement body = compensator_.compensate(increment);

  const NavState old = state_;
  const Eigen::Vector3d earth_rate = earth_.earth_rate_enu_rad_s(old.latitude_rad);
  const Eigen::Vector3d transport_rate =
      earth_.transport_rate_enu_rad_s(old.velocity_enu_m_s, old.latitude_rad, old.height_m);

  // Velocity: specific force rotated with the attitude at the interval start, corrected for the
  // nav frame turning during the interval; gravity and Coriolis from the start-of-interval state.
  // The nav-rotation term acts on the raw increment, so that it cancels the body's (1/2) a x v
  // exactly when the body turns with the nav frame (static on the rotating Earth); on the
  // compensated increment it would add a spurious third-order term zeta x (a x v) / 4.
  const Eigen::Vector3d nav_rotation_start = (earth_rate + transport_rate) * dt;
  const Eigen::Vector3d specific_force_dv = old.q_body_to_enu * body.delta_velocity_m_s;
  const Eigen::Vector3d raw_specific_force_dv = old.q_body_to_enu * increment.delta_velocity_m_s;
  const Eigen::Vector3d gravity(0.0, 0.0, -earth_.gravity_m_s2(old.latitude_rad, old.height_m));
  const Eigen::Vector3d coriolis = -(2.0 * earth_rate + transport_rate).cross(old.velocity_enu_m_s);
  state_.velocity_enu_m_s = old.velocity_enu_m_s + specific_force_dv -
                            0.5 * nav_rotation_start.cross(raw_specific_force_dv) + (gravity + coriolis) * dt;

  // Position: trapezoidal velocity; radii at mid-interval height and latitude.
  const Eigen::Vector3d mean_velocity = 0.5 * (old.velocity_enu_m_s + state_.velocity_enu_m_s);
  state_.height_m = old.height_m + mean_velocity.z() * dt;
  const double mid_height = 0.5 * (old.height_m + state_.height_m);
  state_.latitude_rad =
      old.latitude_rad + mean_velocity.y() / (earth_.meridian_radius_m(old.latitude_rad) + mid_height) * dt;
  const double mid_latitude = 0.5 * (old.latitude_rad + state_.latitude_rad);
  state_.longitude_rad = wrap_longitude(
      old.longitude_rad +
      mean_velocity.x() / ((earth_.prime_vertical_radius_m(mid_latitude) + mid_height) * std::cos(mid_latitude)) * dt);
  const VerticalCorrection height_loop = vertical_.feedback(old.height_m, dt);
  state_.height_m += height_loop.height_m;
  state_.velocity_enu_m_s.z() += height_loop.up_velocity_m_s;

  // Attitude: nav frame rotation at mid-interval, which also keeps the Schuler loop from
  // gaining energy through the explicit velocity step above.
  const Eigen::Vector3d nav_rotation_mid = (earth_.earth_rate_enu_rad_s(mid_latitude) +
                                            earth_.transport_rate_enu_rad_s(mean_velocity, mid_latitude, mid_height)) *
                                           dt;
  state_.q_body_to_enu = propagate_attitude(old.q_body_to_enu, body.rotation_vector_rad, nav_rotation_mid);
  state_.stamp_s = old.stamp_s + dt;
  const std::string problem = state_problem(state_);
  if (!problem.empty()) {
    state_ = old;
    initialised_ = false;
    throw UnusableStateError("nav: the state became unusable in the step ending at t = " +
                             format_number(old.stamp_s + dt, 12) + " s: " + problem);
  }
  return state_;
}

}  // namespace nav
}  // namespace imu_lab
