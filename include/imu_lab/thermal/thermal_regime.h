// The regime indicator of Golovach 2017 eq. 3.18: the thermal regime is dynamic while the second
// derivative of the main thermosensor's temperature exceeds a threshold (the chamber moving to a
// new set point, the sensor's lag still settling), static otherwise; the model then switches
// between two sets of terms (eq. 3.19, ThermalModel::regime_switch). Causal: the indicator at a
// reading uses no later reading, so the live compensator and the offline fit agree sample by
// sample. The thesis's delay is `hold_s`: the dynamic regime lasts that long after the last
// reading over the threshold (effects that lag the housing temperature settle later).
#pragma once

#include <cstdint>
#include <deque>
#include <string>

#include "imu_lab/thermal/temperature_history.h"
#include "imu_lab/thermal/thermal_model.h"

namespace imu_lab {
namespace thermal {

// Throws std::invalid_argument naming the setting (threshold <= 0, window <= 0, hold < 0).
void check_regime_settings(const RegimeSwitchSettings& settings);

class RegimeIndicator {
 public:
  explicit RegimeIndicator(const RegimeSwitchSettings& settings);  // checks the settings

  // Call after each reading added to `history` (the main thermosensor): evaluates |d2T/dt2| at
  // its newest reading.
  void update(const TemperatureHistory& history);
  // Every reading of a whole history, offline (the same values as update() reading by reading).
  void update_all(const TemperatureHistory& history);
  // The regime at a stamp from the readings up to it: dynamic when the last reading at or before
  // it was over the threshold, or one was within hold_s before it.
  bool dynamic_at(std::int64_t stamp_ns) const;
  void drop_before(std::int64_t stamp_ns);  // keeps the reading just before, as the history does

  const RegimeSwitchSettings& settings() const { return settings_; }
  std::size_t readings() const { return stamps_ns_.size(); }
  std::size_t readings_over_threshold() const { return over_threshold_count_; }

 private:
  void add(std::int64_t stamp_ns, double second_derivative_c_s2);

  RegimeSwitchSettings settings_;
  std::deque<std::int64_t> stamps_ns_;
  std::deque<bool> over_;
  std::deque<std::int64_t> last_over_ns_;  // latest stamp over the threshold at or before each reading
  std::size_t over_threshold_count_ = 0;
};

// The default threshold from the data (doc/thermal.md, "Regime switch"): the larger of
//  - 5 sigma of the estimate's noise: sigma_T of one reading from the readings' second differences
//    (white noise, quantisation), through the estimator: sqrt(6 / n) sigma_T / (window / 3)^2 with
//    n readings per third; a steady temperature does not cross it by chance;
//  - a tenth of the largest |d2T/dt2| of the test: the dynamic regime is the part of each
//    transition within 20 dB of the sharpest one (so a noise-free record gets a threshold too).
struct RegimeThresholdSuggestion {
  double threshold_c_s2 = 0.0;
  double noise_c_s2 = 0.0;   // 1 sigma of the estimate
  double peak_c_s2 = 0.0;    // largest |d2T/dt2| of the readings
  std::string text() const;  // "threshold 8.3e-06 degC/s^2 (noise 1.2e-08, peak 8.3e-05)"
};
RegimeThresholdSuggestion suggest_regime_threshold(const TemperatureHistory& history, double window_s);

}  // namespace thermal
}  // namespace imu_lab
