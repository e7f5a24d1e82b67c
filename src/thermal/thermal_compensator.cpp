#include "imu_lab/thermal/thermal_compensator.h"

#include <algorithm>
#include <cmath>

#include "imu_lab/common/stamps.h"
#include "imu_lab/common/usable_imu_values.h"

namespace imu_lab {
namespace thermal {

ThermalCompensator::ThermalCompensator(ThermalModel model, double max_temperature_age_s)
    : model_(std::move(model)), max_temperature_age_s_(max_temperature_age_s) {
  if (model_.regime_switch.enabled) regime_.emplace(model_.regime_switch);
}

bool ThermalCompensator::add_temperature(std::int64_t stamp_ns, double temperature_c,
                                         std::vector<CompensatedSample>* ready) {
  if (!temperature_.add(stamp_ns, temperature_c)) return false;
  if (regime_) regime_->update(temperature_);
  release(false, ready);
  return true;
}

bool ThermalCompensator::add_second_temperature(std::int64_t stamp_ns, double temperature_c,
                                                std::vector<CompensatedSample>* ready) {
  if (!second_temperature_.add(stamp_ns, temperature_c)) return false;
  release(false, ready);
  return true;
}

bool ThermalCompensator::add_imu(const io::ImuRecord& reading, std::vector<CompensatedSample>* ready) {
  if ((newest_imu_stamp_ns_ && reading.stamp_ns <= *newest_imu_stamp_ns_) ||
      !is_usable_imu_vector(reading.angular_rate_rad_s) || !is_usable_imu_vector(reading.specific_force_m_s2)) {
    return false;
  }
  newest_imu_stamp_ns_ = reading.stamp_ns;
  waiting_.push_back(reading);
  release(false, ready);
  return true;
}

void ThermalCompensator::flush(std::vector<CompensatedSample>* ready) { release(true, ready); }

bool ThermalCompensator::has_reading_after(const TemperatureHistory& history, std::int64_t stamp_ns) const {
  return !history.empty() && history.newest_stamp_ns() >= stamp_ns;
}

void ThermalCompensator::release(bool everything, std::vector<CompensatedSample>* ready) {
  while (!waiting_.empty()) {
    const std::int64_t stamp_ns = waiting_.front().stamp_ns;
    const bool bracketed = has_reading_after(temperature_, stamp_ns) &&
                           (!model_.uses_second_sensor || has_reading_after(second_temperature_, stamp_ns));
    const bool given_up = seconds_between(stamp_ns, *newest_imu_stamp_ns_) > max_temperature_age_s_;
    if (!(bracketed || given_up || everything)) break;
    ready->push_back(compensate(waiting_.front()));
    waiting_.pop_front();
  }
  // The rate (and the regime's second derivative) need one window of history; interpolation needs
  // the reading before.
  if (!newest_imu_stamp_ns_) return;
  const double history_s =
      regime_ ? std::max(model_.rate_window_s, model_.regime_switch.window_s) : model_.rate_window_s;
  const std::int64_t keep_from_ns = (waiting_.empty() ? *newest_imu_stamp_ns_ : waiting_.front().stamp_ns) -
                                    stamp_ns_from_seconds(history_s + max_temperature_age_s_);
  temperature_.drop_before(keep_from_ns);
  second_temperature_.drop_before(keep_from_ns);
  if (regime_) regime_->drop_before(keep_from_ns);
}

CompensatedSample ThermalCompensator::compensate(const io::ImuRecord& reading) const {
  CompensatedSample out;
  out.corrected = reading;
  const auto temperature_c = temperature_.temperature_at(reading.stamp_ns, max_temperature_age_s_);
  std::optional<double> second_c;
  if (model_.uses_second_sensor)
    second_c = second_temperature_.temperature_at(reading.stamp_ns, max_temperature_age_s_);
  if (!temperature_c || (model_.uses_second_sensor && !second_c)) {
    out.status = CompensatedSample::Status::kStale;
    return out;
  }
  out.input.temperature_c = *temperature_c;
  out.input.rate_c_s = temperature_.rate_at(reading.stamp_ns, model_.rate_window_s);
  out.input.second_temperature_c = second_c;
  out.input.dynamic_regime = regime_ && regime_->dynamic_at(reading.stamp_ns);
  const ThermalCorrection correction =
      correct(model_, reading.angular_rate_rad_s, reading.specific_force_m_s2, out.input);
  out.corrected.angular_rate_rad_s = correction.angular_rate_rad_s;
  out.corrected.specific_force_m_s2 = correction.specific_force_m_s2;
  out.status = correction.clamped ? CompensatedSample::Status::kClamped : CompensatedSample::Status::kCorrected;
  return out;
}

}  // namespace thermal
}  // namespace imu_lab
