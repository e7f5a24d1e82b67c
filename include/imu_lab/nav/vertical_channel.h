// The vertical channel: free inertial, or held by a reference height through the textbook's
// constant-gain second-order loop (Fomichev 2022 §3.2, eq. 34):
//   dh/dt   = v_up + k1 (h - h_ref)
//   dv_up/dt = f_up - g(h) + k2 (h - h_ref)
// Gravity stays evaluated at the computed height, so losing the reference just switches to free
// (prediction) mode, eq. 38. The error dynamics have the characteristic polynomial
// s^2 - k1 s - (k2 + 2 w0^2); they are stable iff k1 < 0 and k2 < -2 w0^2.
// Free, a height error grows as cosh(sqrt(2) w0 t): e-folding time 1 / (sqrt(2) w0) ~ 570 s.
//
// Default gains: the double root the textbook recommends, with a time constant of 30 s ("tens of
// seconds"): k1 = -2 / tau, k2 = -1 / tau^2 - 2 w0^2 (w0 for WGS-84 at the equator). Held, a
// height error e0 and a constant vertical accelerometer bias b give
//   |h error| <= |e0| + |b| / |k2 + 2 w0^2|     (= |e0| + b tau^2 for the double root),
// tending to -b / (k2 + 2 w0^2) (positive along the bias).
#pragma once

#include <optional>

#include "imu_lab/common/earth_constants.h"

namespace imu_lab {
namespace nav {

enum class VerticalChannelMode { kFree, kHeld };

struct VerticalLoopGains {
  double k1_per_s;
  double k2_per_s2;
};

// Gains giving a double root at -1 / time_constant_s for a Schuler rate w0.
VerticalLoopGains critically_damped_vertical_gains(double time_constant_s, double schuler_rate_rad_s);

struct VerticalCorrection {
  double height_m = 0.0;
  double up_velocity_m_s = 0.0;
};

struct VerticalChannelConfig {
  VerticalChannelMode mode = VerticalChannelMode::kHeld;
  // Defaults: critically_damped_vertical_gains(30 s, sqrt(g_e / a)), WGS-84 at the equator.
  double k1_per_s = -2.0 / 30.0;
  double k2_per_s2 = -1.0 / 900.0 - 2.0 * wgs84::kEquatorialGravity_m_s2 / wgs84::kSemiMajorAxis_m;
  // A fixed reference; without one, the held channel runs free until set_reference_height is called.
  std::optional<double> fixed_reference_height_m;
};

class VerticalChannel {
 public:
  explicit VerticalChannel(const VerticalChannelConfig& config = VerticalChannelConfig());

  // A new reference (e.g. barometer or GNSS height from a topic). Ignored in kFree mode.
  void set_reference_height(double reference_height_m);
  // Reference lost: run free (prediction) until the next set_reference_height.
  void clear_reference_height();
  bool aiding() const;

  // Feedback of eq. (34) over one step of dt_s, from the height at the interval start (which
  // keeps the discrete steady state equal to the continuous one); add it to the free inertial
  // step's height and up velocity. Zero when not aiding.
  VerticalCorrection feedback(double interval_start_height_m, double dt_s) const;

 private:
  VerticalChannelConfig config_;
  std::optional<double> reference_height_m_;
};

}  // namespace nav
}  // namespace imu_lab
