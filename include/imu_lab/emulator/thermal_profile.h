// Exact temperatures of a thermal scenario (see ThermalConfig). In each chamber segment the
// chamber is linear, u(s) = a + b s, and the first-order sensor lag tau1 x' = u - x solves to
//   x(s) = a + b (s - tau1) + D e^{-s/tau1},  D = x(0) - a + b tau1.
// Sensor temperature T(t) = x(t) + F(t), F = p1 e^{p2 t} + p3 e^{p4 t} + p5 (self-heating).
// The second thermosensor y lags T: tau2 y' = T - y, solved term by term (constants, ramps and
// exponentials each have a closed-form response; equal time constants use the s e^{-s/tau} form).
#pragma once

#include <optional>
#include <vector>

#include "imu_lab/emulator/scenario.h"

namespace imu_lab {
namespace emulator {

class ThermalProfile {
 public:
  explicit ThermalProfile(const ThermalConfig& config);

  double chamber_temperature_c(double time_s) const;
  double sensor_temperature_c(double time_s) const;
  double sensor_temperature_rate_c_s(double time_s) const;
  bool has_second_sensor() const { return config_.second_sensor_time_constant_s.has_value(); }
  double second_sensor_temperature_c(double time_s) const;
  // Segment starts: the temperatures' derivatives jump there.
  const std::vector<double>& breakpoints_s() const { return segment_starts_s_; }

 private:
  struct Segment {
    double start_s = 0.0;
    double chamber_start_c = 0.0;     // a
    double chamber_rate_c_s = 0.0;    // b
    double lag_start_c = 0.0;         // x(0)
    double second_lag_start_c = 0.0;  // the second sensor's response to x, at the start
  };
  const Segment& segment_at(double time_s) const;
  double lagged_chamber_c(const Segment& segment, double elapsed_s) const;
  double second_lag_of_chamber_c(const Segment& segment, double elapsed_s) const;
  double self_heating_c(double time_s) const;
  double second_lag_of_self_heating_c(double time_s) const;

  ThermalConfig config_;
  std::vector<Segment> segments_;
  std::vector<double> segment_starts_s_;
};

}  // namespace emulator
}  // namespace imu_lab
