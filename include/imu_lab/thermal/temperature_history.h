// Thermosensor readings indexed by their header stamps, so an IMU sample is matched to the
// temperature at its own stamp (interpolated), never to whichever reading arrived last. The fit
// and the live compensator use the same history, so both see the same temperature and rate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

namespace imu_lab {
namespace thermal {

class TemperatureHistory {
 public:
  // Stamps are header stamps in integer nanoseconds (common/stamps.h). Readings must come in
  // increasing stamp order; returns false (and ignores the reading) for a stamp not after the
  // newest one or a non-finite value.
  bool add(std::int64_t stamp_ns, double temperature_c);
  // Seconds would be truncated to nanoseconds silently: not accepted.
  bool add(double, double) = delete;
  std::optional<double> temperature_at(double, double) const = delete;
  double rate_at(double, double) const = delete;

  bool empty() const { return stamps_ns_.empty(); }
  std::size_t size() const { return stamps_ns_.size(); }
  std::int64_t oldest_stamp_ns() const { return stamps_ns_.front(); }
  std::int64_t newest_stamp_ns() const { return stamps_ns_.back(); }
  // The kept readings, oldest first.
  std::int64_t stamp_ns_at(std::size_t index) const { return stamps_ns_[index]; }
  double temperature_c_at(std::size_t index) const { return temperatures_c_[index]; }

  // Distance in seconds from stamp_ns to the nearest reading (infinite when empty).
  double age_at(std::int64_t stamp_ns) const;
  // Linear interpolation between the readings around stamp_ns; at either end the end reading is
  // held. Empty when the nearest reading is more than max_age_s away (stale).
  std::optional<double> temperature_at(std::int64_t stamp_ns, double max_age_s) const;
  // Rate of change at stamp_ns from the readings in (stamp - window_s, stamp]: the mean of
  // the later half minus the mean of the earlier half, over half the window (exact for a ramp,
  // and robust to a quantised thermosensor). Uses no reading after stamp_s, so a live node
  // gets the same value as an offline pass. Zero until both halves have readings.
  double rate_at(std::int64_t stamp_ns, double window_s) const;
  // Second derivative at stamp_ns from the readings in (stamp - window_s, stamp]: the means over
  // its three thirds, (m3 - 2 m2 + m1) / (window_s / 3)^2 (exact for a parabola, causal as
  // rate_at). Zero until the readings cover the whole window (one at or before its start).
  double second_derivative_at(std::int64_t stamp_ns, double window_s) const;
  double second_derivative_at(double, double) const = delete;

  // Forgets readings older than stamp_ns (keeps the one just before, for interpolation).
  void drop_before(std::int64_t stamp_ns);

 private:
  std::size_t first_after(std::int64_t stamp_ns) const;  // index of the first reading with a later stamp
  double sum_before(std::size_t index) const;            // sum of the readings [0, index)

  std::deque<std::int64_t> stamps_ns_;
  std::deque<double> temperatures_c_;
  std::deque<double> running_sums_c_;  // running_sums_c_[i] = sum of readings (dropped ones too) up to i
  double dropped_sum_c_ = 0.0;         // the running sum just before the first kept reading
};

}  // namespace thermal
}  // namespace imu_lab
