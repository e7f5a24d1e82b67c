#include "imu_lab/nav/vertical_channel.h"

#include <cmath>

#include "imu_lab/common/config_error.h"

namespace imu_lab {
namespace nav {

VerticalLoopGains critically_damped_vertical_gains(double time_constant_s, double schuler_rate_rad_s) {
  if (!(time_constant_s > 0.0)) {
    throw ConfigError("nav", "vertical.time_constant_s", "must be a positive number of seconds");
  }
  return {-2.0 / time_constant_s,
          -1.0 / (time_constant_s * time_constant_s) - 2.0 * schuler_rate_rad_s * schuler_rate_rad_s};
}

VerticalChannel::VerticalChannel(const VerticalChannelConfig& config)
    : config_(config), reference_height_m_(config.fixed_reference_height_m) {
  if (config_.mode == VerticalChannelMode::kHeld) {
    if (!(config_.k1_per_s < 0.0)) {
      throw ConfigError("nav", "vertical.k1_per_s", "must be negative for a stable height loop (Fomichev 2022 eq. 37)");
    }
    if (!(config_.k2_per_s2 < 0.0)) {
      throw ConfigError("nav", "vertical.k2_per_s2",
                        "must be below -2 w0^2 (about -3.1e-6 1/s^2) for a stable height loop");
    }
  }
}

void VerticalChannel::set_reference_height(double reference_height_m) {
  if (!std::isfinite(reference_height_m)) {
    throw InputError("nav: reference height is not finite; drop the sample");
  }
  reference_height_m_ = reference_height_m;
}

void VerticalChannel::clear_reference_height() { reference_height_m_.reset(); }

bool VerticalChannel::aiding() const {
  return config_.mode == VerticalChannelMode::kHeld && reference_height_m_.has_value();
}

VerticalCorrection VerticalChannel::feedback(double interval_start_height_m, double dt_s) const {
  VerticalCorrection correction;
  if (!aiding()) return correction;
  const double height_error_m = interval_start_height_m - *reference_height_m_;
  correction.height_m = config_.k1_per_s * height_error_m * dt_s;
  correction.up_velocity_m_s = config_.k2_per_s2 * height_error_m * dt_s;
  return correction;
}

}  // namespace nav
}  // namespace imu_lab
