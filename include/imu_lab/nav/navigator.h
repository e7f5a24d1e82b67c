// Strapdown navigation from IMU increments (no ROS).
//
//   NavigatorConfig config;                  // Earth model, vertical channel, corrections
//   Navigator navigator(config);
//   navigator.initialise(initial_state);     // attitude from StaticAligner or given
//   const NavState& s = navigator.update(delta_angle_rad, delta_velocity_m_s, dt_s);
//
// Mechanisation (Savage 1998 structure), internally in the local-level ENU frame, so the state is
// exposed as-is (see nav_state.h for the frames):
//  - coning / sculling / rotation compensation of the increments (coning_sculling.h);
//  - velocity: dv = C(k-1) dv_b - zeta/2 x C(k-1) v + (g - (2 w_ie + w_en) x v) dt, with dv_b the
//    compensated and v the raw increment, zeta = (w_ie + w_en) dt from the state at the interval
//    start and normal gravity (earth_model.h);
//  - position: trapezoidal velocity on lat / lon / height with the ellipsoid's radii;
//  - vertical channel feedback (vertical_channel.h);
//  - attitude: q(k) = exp(-zeta) q(k-1) exp(phi), zeta evaluated at mid-interval, normalised.
// Not valid within a few metres of the poles (ENU and longitude are singular there).
//
// The navigator checks its own state after every step (state_problem): NaN/Inf anywhere, a latitude
// at or beyond a pole, or a height beyond +-1000 km (kMaxAbsoluteHeight_m) means the input was
// absurd (units, a wild sample) or the free vertical channel has run away; update() then throws
// UnusableStateError and the navigator stops until initialise() is called again.
#pragma once

#include <Eigen/Core>
#include <string>

#include "imu_lab/common/config_error.h"

#include "imu_lab/nav/coning_sculling.h"
#include "imu_lab/nav/earth_model.h"
#include "imu_lab/nav/imu_increment.h"
#include "imu_lab/nav/nav_state.h"
#include "imu_lab/nav/vertical_channel.h"

namespace imu_lab {
namespace nav {

// Beyond this height no vehicle the navigator serves can be, and normal gravity's height
// correction (earth_model.h, second order in h / a) is no longer a model of anything.
constexpr double kMaxAbsoluteHeight_m = 1.0e6;

// Why a state cannot be navigated from or published (empty when it can): NaN/Inf in any field or
// a zero quaternion, a latitude not strictly between the poles, |height| > kMaxAbsoluteHeight_m.
std::string state_problem(const NavState& state);

// The step that made the state unusable: bad data, so an InputError.
class UnusableStateError : public InputError {
 public:
  using InputError::InputError;
};

struct NavigatorConfig {
  EarthModelConfig earth;
  VerticalChannelConfig vertical;
  ConingScullingConfig corrections;
};

class Navigator {
 public:
  explicit Navigator(const NavigatorConfig& config = NavigatorConfig());

  // Starts (or restarts) navigation from a known state; forgets the previous increment.
  // Throws InputError naming the problem for a state state_problem() refuses.
  void initialise(const NavState& initial_state);
  bool initialised() const { return initialised_; }

  // One IMU interval: increments in the body frame; stamp advances by dt_s.
  // Throws std::logic_error before initialise(), InputError for a bad increment, and
  // UnusableStateError when the new state is unusable (state_problem); then state() keeps the last
  // usable state and initialised() is false until the next initialise().
  const NavState& update(const Eigen::Vector3d& delta_angle_rad, const Eigen::Vector3d& delta_velocity_m_s,
                         double dt_s);
  const NavState& update(const ImuIncrement& increment);

  // Height aiding for the held vertical channel (e.g. from a barometer topic).
  void set_reference_height(double reference_height_m) { vertical_.set_reference_height(reference_height_m); }
  void clear_reference_height() { vertical_.clear_reference_height(); }

  const NavState& state() const { return state_; }
  const EarthModel& earth() const { return earth_; }

 private:
  EarthModel earth_;
  VerticalChannel vertical_;
  ConingScullingCompensator compensator_;
  NavState state_;
  bool initialised_ = false;
};

}  // namespace nav
}  // namespace imu_lab
