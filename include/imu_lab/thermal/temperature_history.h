// Thermosensor readings indexed by their header stamps, so an IMU sample is matched to the
// temperature at its own stamp (interpolated), never to whichever reading arrived last. The fit
// and the live compensator use the same history, so both see the same temperature and rate.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>

namespace imu_lab {
namespace thermal {

class TemperatureHistory {
 public:
  // Readings must come in increasing stamp order; returns false (and ignores the reading) for a
  // stamp not after the newest one or a non-finite value.
  bool add(double stamp_s, double temperature_c);

  bool empty() const { return stamps_s_.empty(); }
  std::size_t size() const { return stamps_s_.size(); }
  double oldest_stamp_s() const { return stamps_s_.front(); }
  double newest_stamp_s() const { return stamps_s_.back(); }

  // Distance from stamp_s to the nearest reading (infinite when empty).
  double age_at(double stamp_s) const;
  // Linear interpolation between the readings around stamp_s; at either end the end reading is
  // held. Empty when the nearest reading is more than max_age_s away (stale).
  std::optional<double> temperature_at(double stamp_s, double max_age_s) const;
  // Rate of change at stamp_s from the readings in (stamp_s - window_s, stamp_s]: the mean of
  // the later half minus the mean of the earlier half, over half the window (exact for a ramp,
  // and robust to a quantised thermosensor). Uses no reading after stamp_s, so a live node
  // gets the same value as an offline pass. Zero until both halves have readings.
  double rate_at(double stamp_s, double window_s) const;

  // Forgets readings older than stamp_s (keeps the one just before, for interpolation).
  void drop_before(double stamp_s);

 private:
  std::size_t first_after(double stamp_s) const;  // index of the first reading with stamp > stamp_s
  double sum_before(std::size_t index) const;     // sum of the readings [0, index)

  std::deque<double> stamps_s_;
  std::deque<double> temperatures_c_;
  std::deque<double> running_sums_c_;  // running_sums_c_[i] = sum of readings (dropped ones too) up to i
  double dropped_sum_c_ = 0.0;         // the running sum just before the first kept reading
};

}  // namespace thermal
}  // namespace imu_lab
