#include "imu_lab/emulator/thermal_profile.h"

#include <algorithm>
#include <cmath>

namespace imu_lab {
namespace emulator {

namespace {

// Response of the lag tau2 y' = u - y, started at y(0) = y0, to u(s) = c e^{-s/tau1}
// (the part of the input that decays with tau1); the resonant case tau1 = tau2 has s e^{-s/tau}.
double second_lag_of_exponential(double c, double tau1, double tau2, double y0, double s) {
  if (std::abs(tau1 - tau2) <= 1e-9 * tau1) {
    return (y0 + c * s / tau2) * std::exp(-s / tau2);
  }
  const double gain = tau1 / (tau1 - tau2);
  return c * gain * std::exp(-s / tau1) + (y0 - c * gain) * std::exp(-s / tau2);
}

// Same for u(s) = c e^{lambda s} with any lambda (self-heating terms, lambda = p2, p4).
double second_lag_of_growth(double c, double lambda, double tau2, double y0, double s) {
  return second_lag_of_exponential(c, -1.0 / lambda, tau2, y0, s);
}

}  // namespace

ThermalProfile::ThermalProfile(const ThermalConfig& config) : config_(config) {
  Segment segment;
  segment.chamber_start_c = config.initial_chamber_temperature_c;
  segment.lag_start_c = segment.chamber_start_c;
  segment.second_lag_start_c = segment.chamber_start_c;
  auto push = [&](double rate_c_s) {
    segment.chamber_rate_c_s = rate_c_s;
    segments_.push_back(segment);
    segment_starts_s_.push_back(segment.start_s);
  };
  for (const ThermalConfig::Segment& configured : config.segments) {
    push(configured.rate_c_s);
    const double d = configured.duration_s;
    const Segment& done = segments_.back();
    segment.start_s = done.start_s + d;
    segment.chamber_start_c = done.chamber_start_c + done.chamber_rate_c_s * d;
    segment.lag_start_c = lagged_chamber_c(done, d);
    segment.second_lag_start_c = second_lag_of_chamber_c(done, d);
  }
  push(0.0);  // the chamber holds its last set point
}

const ThermalProfile::Segment& ThermalProfile::segment_at(double time_s) const {
  auto after = std::upper_bound(segment_starts_s_.begin(), segment_starts_s_.end(), time_s);
  return segments_[after == segment_starts_s_.begin() ? 0 : (after - segment_starts_s_.begin()) - 1];
}

double ThermalProfile::lagged_chamber_c(const Segment& segment, double elapsed_s) const {
  const double tau1 = config_.sensor_time_constant_s;
  const double a = segment.chamber_start_c, b = segment.chamber_rate_c_s;
  const double decaying = segment.lag_start_c - a + b * tau1;
  return a + b * (elapsed_s - tau1) + decaying * std::exp(-elapsed_s / tau1);
}

double ThermalProfile::second_lag_of_chamber_c(const Segment& segment, double elapsed_s) const {
  if (!has_second_sensor()) return 0.0;
  const double tau1 = config_.sensor_time_constant_s;
  const double tau2 = *config_.second_sensor_time_constant_s;
  const double a = segment.chamber_start_c, b = segment.chamber_rate_c_s;
  const double decaying = segment.lag_start_c - a + b * tau1;
  // The ramp a - b tau1 + b s lags to a - b tau1 + b (s - tau2) plus its own decay.
  const double ramp_response = a - b * tau1 + b * (elapsed_s - tau2);
  const double ramp_start = a - b * tau1 - b * tau2;
  const double y0_of_rest = segment.second_lag_start_c - ramp_start;
  return ramp_response + second_lag_of_exponential(decaying, tau1, tau2, y0_of_rest, elapsed_s);
}

double ThermalProfile::self_heating_c(double time_s) const {
  return config_.p1_c * std::exp(config_.p2_per_s * time_s) + config_.p3_c * std::exp(config_.p4_per_s * time_s) +
         config_.p5_c;
}

double ThermalProfile::second_lag_of_self_heating_c(double time_s) const {
  // Started in equilibrium: each term's lag begins at the term's own value.
  const double tau2 = *config_.second_sensor_time_constant_s;
  double total = config_.p5_c;
  for (const auto& [c, lambda] :
       {std::pair{config_.p1_c, config_.p2_per_s}, std::pair{config_.p3_c, config_.p4_per_s}}) {
    total += lambda == 0.0 ? c : second_lag_of_growth(c, lambda, tau2, c, time_s);
  }
  return total;
}

double ThermalProfile::chamber_temperature_c(double time_s) const {
  const Segment& segment = segment_at(time_s);
  return segment.chamber_start_c + segment.chamber_rate_c_s * std::max(0.0, time_s - segment.start_s);
}

double ThermalProfile::sensor_temperature_c(double time_s) const {
  const Segment& segment = segment_at(time_s);
  return lagged_chamber_c(segment, std::max(0.0, time_s - segment.start_s)) + self_heating_c(time_s);
}

double ThermalProfile::sensor_temperature_rate_c_s(double time_s) const {
  const double lag_rate = (chamber_temperature_c(time_s) - (sensor_temperature_c(time_s) - self_heating_c(time_s))) /
                          config_.sensor_time_constant_s;
  return lag_rate + config_.p1_c * config_.p2_per_s * std::exp(config_.p2_per_s * time_s) +
         config_.p3_c * config_.p4_per_s * std::exp(config_.p4_per_s * time_s);
}

double ThermalProfile::second_sensor_temperature_c(double time_s) const {
  if (!has_second_sensor()) return sensor_temperature_c(time_s);
  const Segment& segment = segment_at(time_s);
  return second_lag_of_chamber_c(segment, std::max(0.0, time_s - segment.start_s)) +
         second_lag_of_self_heating_c(time_s);
}

}  // namespace emulator
}  // namespace imu_lab
