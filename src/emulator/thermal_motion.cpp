#include "imu_lab/emulator/thermal_motion.h"

#include <algorithm>
#include <cmath>

#include "imu_lab/emulator/piecewise_quadrature.h"

namespace imu_lab {
namespace emulator {

ThermalMotion::ThermalMotion(std::unique_ptr<MotionSource> motion, const ThermalConfig& thermal)
    : motion_(std::move(motion)), profile_(thermal) {
  // Keep each piece within a fraction of the fastest exponential's time scale.
  longest_piece_s_ = std::min(1.0, 0.5 * thermal.sensor_time_constant_s);
  if (thermal.second_sensor_time_constant_s) {
    longest_piece_s_ = std::min(longest_piece_s_, 0.5 * *thermal.second_sensor_time_constant_s);
  }
  for (double rate_per_s : {thermal.p2_per_s, thermal.p4_per_s}) {
    if (rate_per_s != 0.0) longest_piece_s_ = std::min(longest_piece_s_, 0.5 / std::abs(rate_per_s));
  }
}

TruthIncrement ThermalMotion::increment(double start_s, double interval_s) {
  TruthIncrement result = motion_->increment(start_s, interval_s);
  const double end_s = start_s + interval_s;
  auto mean_of = [&](auto temperature_at) {
    return integrate_smooth_pieces(temperature_at, start_s, interval_s, profile_.breakpoints_s(), longest_piece_s_,
                                   0.0) /
           interval_s;
  };
  result.mean_temperature_c = mean_of([this](double t) { return profile_.sensor_temperature_c(t); });
  result.mean_temperature_rate_c_s =
      (profile_.sensor_temperature_c(end_s) - profile_.sensor_temperature_c(start_s)) / interval_s;
  if (profile_.has_second_sensor()) {
    result.mean_second_temperature_c = mean_of([this](double t) { return profile_.second_sensor_temperature_c(t); });
  }
  return result;
}

TruthState ThermalMotion::truth_at(double time_s) const {
  TruthState truth = motion_->truth_at(time_s);
  truth.temperature_c = profile_.sensor_temperature_c(time_s);
  truth.temperature_rate_c_s = profile_.sensor_temperature_rate_c_s(time_s);
  if (profile_.has_second_sensor()) truth.second_temperature_c = profile_.second_sensor_temperature_c(time_s);
  return truth;
}

}  // namespace emulator
}  // namespace imu_lab
