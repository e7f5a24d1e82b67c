// Live thermal compensation of an IMU stream: IMU samples and thermosensor readings arrive on
// separate topics in any interleaving; each IMU sample is corrected with the temperature at its
// own stamp. A sample waits until a reading at or after its stamp has arrived (so it is
// interpolated, exactly as offline), or until newer IMU samples show that the temperature is
// more than max_temperature_age_s behind; then the nearest reading is used if it is within
// max_temperature_age_s, otherwise the sample is reported stale and not corrected.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "imu_lab/thermal/temperature_history.h"
#include "imu_lab/thermal/thermal_model.h"
#include "imu_lab/thermal/thermal_regime.h"
#include "imu_lab/thermal/thermal_windows.h"

namespace imu_lab {
namespace thermal {

struct CompensatedSample {
  enum class Status { kCorrected, kClamped, kStale };
  Status status = Status::kCorrected;
  io::ImuRecord corrected;  // the raw reading when stale
  ThermalInput input;       // what the correction used (before clamping)
};

class ThermalCompensator {
 public:
  // A model with the regime switch gets its indicator (thermal_regime.h) fed by the main
  // thermosensor; throws std::invalid_argument for bad regime settings.
  ThermalCompensator(ThermalModel model, double max_temperature_age_s);

  // Each returns the samples that became decidable, in stamp order. Out-of-order or non-finite
  // readings are refused (false / counted) and change nothing.
  // Stamps in integer nanoseconds (common/stamps.h).
  bool add_temperature(std::int64_t stamp_ns, double temperature_c, std::vector<CompensatedSample>* ready);
  bool add_second_temperature(std::int64_t stamp_ns, double temperature_c, std::vector<CompensatedSample>* ready);
  // Seconds would be truncated to nanoseconds silently: not accepted.
  bool add_temperature(double, double, std::vector<CompensatedSample>*) = delete;
  bool add_second_temperature(double, double, std::vector<CompensatedSample>*) = delete;
  bool add_imu(const io::ImuRecord& reading, std::vector<CompensatedSample>* ready);
  // Decides every waiting sample with what has arrived (end of a bag).
  void flush(std::vector<CompensatedSample>* ready);

  const ThermalModel& model() const { return model_; }
  std::size_t waiting() const { return waiting_.size(); }

 private:
  void release(bool everything, std::vector<CompensatedSample>* ready);
  bool has_reading_after(const TemperatureHistory& history, std::int64_t stamp_ns) const;
  CompensatedSample compensate(const io::ImuRecord& reading) const;

  ThermalModel model_;
  double max_temperature_age_s_;
  TemperatureHistory temperature_;
  TemperatureHistory second_temperature_;
  std::optional<RegimeIndicator> regime_;
  std::deque<io::ImuRecord> waiting_;
  std::optional<std::int64_t> newest_imu_stamp_ns_;
};

}  // namespace thermal
}  // namespace imu_lab
